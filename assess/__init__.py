"""assess: seismic response of freestanding building contents.

A freestanding item (incubator, freezer, cabinet, rack) is modelled as a rigid
block on a moving floor, after Konstantinidis & Makris (2010), Bull. Earthquake
Eng. 8:1457-1477, doi:10.1007/s10518-010-9192-8.

The data flow through the sub-packages in this order:
``inventory`` (workbook -> SI tables) -> ``site`` and ``hazard`` (levels,
ground motions) -> ``building`` (every floor's motion) -> ``mechanics``
(the rigid-body engine) -> ``fragility`` (IM, EDP, regression, probability of
exceeding the clearance) -> ``decision`` (risk class, action, cost, with the
``anchorage`` forces) -> ``report``. ``assessment`` holds the stages, the
sequencer (``assess.assessment.pipeline``) and the result; ``portfolio`` runs
and reports many buildings; ``calibration`` fits the model to measured tests;
``command`` is the command's plumbing (its jobs, files, folders, Ctrl-C) and
``assess.cli`` only parses arguments.
"""

__version__ = "0.1.0"
