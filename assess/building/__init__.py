"""The building under its ground motion: modes, floor accelerations in time, and the floors table."""
