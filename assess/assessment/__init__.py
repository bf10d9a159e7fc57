"""The stages of an assessment, in the order :mod:`assess.pipeline` runs them.

inputs -> motions (per floor) -> cases -> run (the engine) -> demand -> decisions
(:mod:`assess.decisions`) -> summary (the result). Each stage is a module of pure
functions with a typed output; none of them calls another stage.
"""
