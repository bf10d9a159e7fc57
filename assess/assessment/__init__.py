"""The stages of an assessment, in the order :mod:`assess.assessment.pipeline` runs them.

inputs -> motions (per floor) -> cases -> run (the engine) -> demand -> decisions
(:mod:`assess.decision.decisions`) -> summary (the result). Each stage is a module of
functions with a typed output (a dataclass or a table whose columns its
docstring declares); only ``run`` starts the engine, and only the decisions
module decides.
"""
