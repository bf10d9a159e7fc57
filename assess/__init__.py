"""assess: seismic response of freestanding building contents.

A freestanding item (incubator, freezer, cabinet, rack) is modelled as a rigid
block on a moving floor, after Konstantinidis & Makris (2010), Bull. Earthquake
Eng. 8:1457-1477, doi:10.1007/s10518-010-9192-8.

The data flow through the sub-packages in this order:
``inventory`` (workbook -> SI tables) -> ``hazard`` (levels, motions) ->
``mechanics`` (geometry, mode of response) -> ``fragility`` (IM, EDP,
regression, probability of exceeding the clearance) -> ``report``.
``assess.pipeline`` sequences them; ``assess.cli`` only parses arguments.
"""

__version__ = "0.1.0"
