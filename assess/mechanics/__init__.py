"""Mechanics of a freestanding rigid block: geometry and mode of response."""
