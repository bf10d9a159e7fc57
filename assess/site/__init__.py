"""The site's hazard: design and uniform-hazard target spectra, and ground suites matched to them.

``spectrum`` (response spectra of records), ``asce7`` (ASCE 7-16 / 7-22 design
spectra), ``uhs`` (OpenQuake uniform-hazard spectra), ``suite`` (a level's
ground suite: records selected and scaled, or synthetic motions matched).
"""
