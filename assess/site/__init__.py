"""The site's hazard: design and uniform-hazard target spectra, and ground suites matched to them.

Modules: ``spectrum`` (response spectra of records), ``asce7`` (ASCE 7-16 / 7-22 design
spectra), ``uhs`` (OpenQuake uniform-hazard spectra, maps and
curves), ``target`` (which spectrum a level names), ``suite`` (a level's ground suite: records
selected and scaled, or synthetic motions matched).

The sequence a job follows with a ``site`` sheet (read and checked by
:mod:`assess.inventory.site_building`; :mod:`assess.assessment.floors` runs it)::

    design = asce7.from_design_values(sds_g, sd1_g, tl_s, code)   # or from_mapped_values(...), or None
    target = target.level_target(level, design=design, uhs_path=..., oq_site=parse_site_choice(...))
    ground = suite.ground_suite(target, periods_that_matter_s, level=level.name,
                                records_folder=folder_or_None, suite_size=11, base_seed=seed)
    ground.motions / ground.records          # the level's ground motions (Record, scaled or matched)
    ground.ground_motions, ground.spectrum   # the rows of ground_motions.csv and spectrum.csv
"""
