"""The workbook's ``site`` and ``building`` sheets: the hazard and the structure as a user has them.

Both are ``key`` / ``value`` sheets like ``settings`` (``docs/workbook.md``). They are read into two
small frozen records, :class:`SiteSheet` and :class:`BuildingSheet`, with every value checked and in
SI units; turning them into target spectra, ground suites and floor motions is the work of
:mod:`assess.site` and :mod:`assess.building`.

A key may carry a unit suffix where the quantity has one (``height_m``, ``height_ft``,
``storey_height_m``, ``tl_s``): the same suffixes, converted once with pint, as the equipment
columns (:mod:`assess.inventory.units`).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from assess.inventory import schema
from assess.inventory.schema import CellError, Column
from assess.building.period import SYSTEMS, approximate_period  # ASCE 7 Table 12.8-2's systems, Eq. 12.8-7
from assess.inventory.units import LENGTH, PERIOD

#: Code editions whose spectra and equations the tool applies.
CODES = ("ASCE 7-22", "ASCE 7-16")
DEFAULT_CODE = "ASCE 7-22"
#: Site classes of ASCE 7-22 Table 20.2-1 (7-16 has A-F without the intermediate BC, CD, DE).
SITE_CLASSES = ("A", "B", "BC", "C", "CD", "D", "DE", "E")
SITE_CLASSES_7_16 = ("A", "B", "C", "D", "E")
#: Risk categories of ASCE 7 Table 1.5-1 (a hospital with surgery or emergency treatment is IV).
RISK_CATEGORIES = ("I", "II", "III", "IV")
DEFAULT_RISK_CATEGORY = "II"
#: Motions in a level's ground suite: ASCE 7-22 §16.2.2 asks for at least 11.
MIN_SUITE_SIZE, MAX_SUITE_SIZE = 3, 500
DEFAULT_DAMPING = 0.05
MAX_STOREYS = 200
#: How a records folder's suite is fitted to its target (``records_scaling`` of the site sheet): each record
#: amplitude-scaled, or spectrally matched (ASCE 7-22 §16.2.3.2, §16.2.3.3; :func:`assess.site.suite.ground_suite`).
RECORDS_SCALINGS = ("amplitude", "matched")
#: How the building answers its ground motions (``response`` of the building sheet): its elastic modes, or a
#: stick of yielding storey springs (:mod:`assess.building.yielding`). Without the key: yielding where the
#: storeys' strength is known (the site sheet's design values, or ``yield_base_shear_g``), elastic otherwise.
RESPONSES = ("elastic", "yielding")
#: The most storeys the yielding stick takes. Each integration step solves the stick's full stiffness (its
#: elastic column or wall couples every floor), so one ground motion costs about the cube of the storeys:
#: per 30 s of shaking, 0.07 / 0.50 / 3.0 / 6.0 s for steel moment frames of 12 / 24 / 40 / 48 storeys, 0.24 /
#: 1.15 / 4.7 / 8.1 s for shear walls and 0.29 / 2.3 / 14 / 28 s for braced frames, whose stiffer column (α 4)
#: shortens the stick's shortest period and with it the step (9.6 / 18 s eccentrically braced at 40 / 48;
#: ``benchmarks/bench_yielding_floor_histories.py --storeys 12,24,40,48``; 93 s for a moment frame of 96; a given
#: ``lateral_stiffness_ratio`` below the system's costs more the same way: 31 s at α 1 for a braced frame of 40), and
#: a level's suite has 11 to 500 motions. Beyond it the elastic modes answer (any
#: height, in seconds), and the note says why.
MAX_YIELDING_STOREYS = 40
#: A given T1 below ASCE 7's approximate period T_a over this is refused: T_a = C_t h_n^x is itself near the
#: short end of buildings' measured periods (meant to err short: ASCE 7's commentary to §12.8.2), and a quarter of it
#: is a unit slip (a frequency, milliseconds) rather than a building. It also bounds the yielding model's
#: cost, whose steps shorten with the stick's shortest period.
PERIOD_BELOW_APPROXIMATE = 4
#: Bounds of the building sheet's ``yield_base_shear_g`` (base shear at yield over the weight) and ``overstrength``.
YIELD_BASE_SHEAR_RANGE_G = (0.01, 3.0)
OVERSTRENGTH_RANGE = (1.0, 6.0)
#: Bounds of the building sheet's ``lateral_stiffness_ratio`` α (Miranda & Taghavi 2005: 0 a flexural cantilever,
#: ∞ a shear building; walls 0 to 2, dual systems 1.5 to 6, moment frames 5 to 20). Below 0.1 the building
#: bends as a cantilever, beyond 30 it shears as a shear building: nothing changes outside these.
LATERAL_STIFFNESS_RATIO_RANGE = (0.1, 30.0)
#: Bounds of the building sheet's ``pushover_slope_ratio`` (the pushover's slope at 2 % roof drift over its
#: initial slope): above 0 (a pushover that falls at 2 % has no α to tell, P-Delta having taken over) and below 1
#: (a building that has not yielded by then).
PUSHOVER_SLOPE_RATIO_RANGE = (0.001, 0.99)
#: Bounds of the building sheet's ``storey_hardening_ratio`` b (a storey's stiffness after yield over its stiffness
#: before): 0 an elastic-perfectly-plastic storey; models of steel and concrete frames take about 0.01 to 0.05
#: (:data:`assess.building.nonlinear.DEFAULT_HARDENING`); beyond 0.2 a storey barely yields.
STOREY_HARDENING_RATIO_RANGE = (0.0, 0.2)
#: The lateral systems whose α a pushover's slope after yield tells: those whose stick keeps the elastic model's
#: column beside its storey springs (:data:`assess.building.nonlinear.FLEXURE_BY_SYSTEM`).
PUSHOVER_ALPHA_SYSTEMS = ("steel moment frame", "concrete moment frame", "eccentrically braced frame",
                          "braced frame")
#: Bounds of the site sheet's T_s = S_D1/S_DS [s], the corner of its design spectrum: a mapped site's is about 0.15
#: to 2 s (rock in a high-hazard region to soft soil in a low one, ASCE 7 Tables 11.4-1 and 11.4-2's site
#: coefficients over the maps' S_S and S_1); outside these, one of the two values is not the site's (a
#: factor slipped, or the two come from different lookups).
CORNER_PERIOD_RANGE_S = (0.05, 5.0)
#: The largest ratio of one storey's stiffness (strength) to another's that the building sheet's ``storey_stiffness``
#: (``storey_strength``) may give.
STOREY_STIFFNESS_SPREAD = 20.0
_YES, _NO = ("yes", "y", "true", "1"), ("no", "n", "false", "0")

_ROMAN = {"1": "I", "2": "II", "3": "III", "4": "IV"}


def too_tall_to_yield(storeys: int) -> bool:
    """Whether a building of ``storeys`` has more than the yielding model takes (:data:`MAX_YIELDING_STOREYS`).

    >>> too_tall_to_yield(40), too_tall_to_yield(41)
    (False, True)
    """
    return int(storeys) > MAX_YIELDING_STOREYS


@dataclass(frozen=True)
class SiteSheet:
    """The ``site`` sheet, checked (``docs/workbook.md``, sheet ``site``).

    Attributes
    ----------
    code : str
        ``ASCE 7-22`` or ``ASCE 7-16``.
    sds_g, sd1_g : float or None
        Design spectral accelerations at short periods and at 1 s [g].
    ss_g, s1_g : float or None
        Mapped MCE_R spectral accelerations [g]; with ``site_class`` they give SDS, SD1.
    site_class : str or None
        ``A`` ... ``E`` (with ``BC``, ``CD``, ``DE`` under ASCE 7-22).
    tl_s : float or None
        Long-period transition period [s]; None when not given (the spectrum then has no T > TL
        branch, which bends it only beyond 4-16 s, above the periods of buildings and equipment).
    risk_category : str
        ``I`` ... ``IV``.
    uhs_path : str
        Absolute path of an OpenQuake uniform-hazard-spectrum export, "" when none.
    oq_site : str
        The site to pick in a ``uhs`` file of several ("" when not given).
    records_folder : str
        Absolute path of a folder of ground-motion records, "" when none.
    records_scaling : str
        How the records are fitted to the target, one of :data:`RECORDS_SCALINGS` (``amplitude`` when not given).
    suite_size : int or None
        Motions in a level's ground suite; None: the default of its route
        (:data:`assess.site.suite.DEFAULT_SUITE_SIZE` records, :data:`assess.site.suite.SYNTHETIC_SUITE_SIZE`
        synthetic motions).
    rows : dict
        The sheet row of each key given, to locate later problems.
    sheet : str
        The sheet's title as written.
    """

    code: str = DEFAULT_CODE
    sds_g: float | None = None
    sd1_g: float | None = None
    ss_g: float | None = None
    s1_g: float | None = None
    site_class: str | None = None
    tl_s: float | None = None
    risk_category: str = DEFAULT_RISK_CATEGORY
    uhs_path: str = ""
    oq_site: str = ""
    records_folder: str = ""
    suite_size: int | None = None
    records_scaling: str = "amplitude"
    rows: dict = field(default_factory=dict, compare=False)
    sheet: str = "site"

    @property
    def has_design_values(self) -> bool:
        """True when SDS and SD1 are given (directly, or from SS, S1 and the site class)."""
        return self.sds_g is not None or self.ss_g is not None


@dataclass(frozen=True)
class BuildingSheet:
    """The ``building`` sheet, checked (``docs/workbook.md``, sheet ``building``).

    Attributes
    ----------
    storeys : int
        Storeys above ground; floors are numbered 0 (ground) to ``storeys`` (roof).
    height_m : float
        Height of the roof above the ground floor [m].
    system : str
        One of :data:`SYSTEMS`.
    period_s : float or None
        The fundamental period T1 where known [s]; None: the code's estimate.
    damping : float
        Modal damping ratio [-].
    response : str or None
        ``elastic`` or ``yielding`` as the sheet says; None where it does not (:meth:`response_with`).
    yield_base_shear_g : float or None
        Base shear at yield over the weight [-] (a pushover, an evaluation), where known.
    overstrength : float or None
        Actual over design base shear, where the engineer sets it (else the default of
        :mod:`assess.building.design`).
    p_delta : bool
        Whether the yielding stick carries the gravity loads' P-Delta stiffness.
    storey_stiffness : tuple of float or None
        The storeys' relative stiffnesses, the first storey to the roof (``uniform``: all 1), where the
        engineer gives them; None: the system's design profile
        (:func:`assess.building.design.design_storey_stiffness`).
    lateral_stiffness_ratio : float or None
        Miranda & Taghavi's α of the building's shear-flexural model, where the engineer gives it; None: the
        system's (:data:`assess.building.ALPHA_BY_SYSTEM`), or the one ``pushover_slope_ratio`` gives.
    pushover_slope_ratio : float or None
        The slope of the engineer's pushover at 2 % roof drift over its initial slope, where given: the yielding
        stick's α is then the one whose own pushover has that slope (:mod:`assess.building.pushover`).
    storey_hardening_ratio : float or None
        The storeys' stiffness after yield over their stiffness before (a wall's: its base's), where the engineer
        gives the model's; None: :data:`assess.building.nonlinear.DEFAULT_HARDENING`.
    brace_buckling : bool
        Whether a braced frame's storeys are its braces, the pushed one buckling (the ``buckling`` law of
        :mod:`assess.building.hysteresis`), where the bilinear springs are the default.
    storey_strength : tuple of float or None
        The storeys' relative strengths, the first storey to the roof, where the engineer gives the model's
        (:func:`assess.building.nonlinear.given_strength`); None: the system's rule
        (:data:`assess.building.nonlinear.STRENGTH_BY_SYSTEM`).
    rows : dict
        The sheet row of each key given.
    sheet : str
        The sheet's title as written.
    """

    storeys: int
    height_m: float
    system: str = "other"
    period_s: float | None = None
    damping: float = DEFAULT_DAMPING
    response: str | None = None
    yield_base_shear_g: float | None = None
    overstrength: float | None = None
    p_delta: bool = False
    storey_stiffness: tuple | None = None
    lateral_stiffness_ratio: float | None = None
    pushover_slope_ratio: float | None = None
    storey_hardening_ratio: float | None = None
    brace_buckling: bool = False
    storey_strength: tuple | None = None
    #: Where α comes from where the run sets it itself (``--alpha-range``'s ends), in words for the notes.
    alpha_source: str = ""
    #: Where ``storey_hardening_ratio`` comes from where the run sets it itself (``--alpha-range``'s ends).
    hardening_source: str = ""
    rows: dict = field(default_factory=dict, compare=False)
    sheet: str = "building"

    @property
    def roof_floor(self) -> int:
        return self.storeys

    @property
    def too_tall_to_yield(self) -> bool:
        """Whether the building has more storeys than the yielding model takes (:func:`too_tall_to_yield`)."""
        return too_tall_to_yield(self.storeys)

    def response_with(self, site: "SiteSheet | None") -> str:
        """``elastic`` or ``yielding``: the sheet's ``response``, else yielding where the storeys' strength is
        known (``yield_base_shear_g``, or the site sheet's design values for the code's design) and the building
        has at most :data:`MAX_YIELDING_STOREYS` storeys, else elastic.

        >>> BuildingSheet(storeys=3, height_m=10.0).response_with(None)
        'elastic'
        >>> BuildingSheet(storeys=3, height_m=10.0).response_with(SiteSheet(sds_g=1.0, sd1_g=0.6))
        'yielding'
        """
        if self.response is not None:
            return self.response
        known = self.yield_base_shear_g is not None or (site is not None and site.has_design_values)
        return "yielding" if known and not self.too_tall_to_yield else "elastic"


# ---------------------------------------------------------------- reading

#: Keys of each sheet: name -> (column for the cell parser, what the value is).
_SITE_KEYS = {
    "code": Column("code", "text", max_chars=40),
    "sds": Column("sds", "number", low=0.01, high=5.0, positive=True),
    "sd1": Column("sd1", "number", low=0.01, high=5.0, positive=True),
    "ss": Column("ss", "number", low=0.01, high=7.5, positive=True),
    "s1": Column("s1", "number", low=0.01, high=3.0, positive=True),
    "site_class": Column("site_class", "text", max_chars=20),
    "tl": Column("tl", "number", dimension=PERIOD, spec_suffix="s", low=1.0, high=20.0, positive=True),
    "risk_category": Column("risk_category", "text", max_chars=20),
    "uhs": Column("uhs", "path", max_chars=255),
    "oq_site": Column("oq_site", "text", max_chars=100),
    "records": Column("records", "path", max_chars=255),
    "suite_size": Column("suite_size", "integer", low=MIN_SUITE_SIZE, high=MAX_SUITE_SIZE),
    "records_scaling": Column("records_scaling", "text", max_chars=20),
}
#: Keys written with their only unit, g (``sds_g``), besides the bare name.
_G_KEYS = ("sds", "sd1", "ss", "s1", "yield_base_shear")
_BUILDING_KEYS = {
    "storeys": Column("storeys", "integer", low=1, high=MAX_STOREYS),
    "height": Column("height", "number", dimension=LENGTH, spec_suffix="m", low=2.0, high=1000.0,
                     positive=True),
    "storey_height": Column("storey_height", "number", dimension=LENGTH, spec_suffix="m", low=2.0,
                            high=10.0, positive=True),
    "system": Column("system", "text", max_chars=60),
    "period": Column("period", "number", dimension=PERIOD, spec_suffix="s", low=0.02, high=15.0,
                     positive=True),
    "damping": Column("damping", "number", low=0.0, high=0.3),
    "response": Column("response", "text", max_chars=20),
    "yield_base_shear": Column("yield_base_shear", "number", low=YIELD_BASE_SHEAR_RANGE_G[0],
                               high=YIELD_BASE_SHEAR_RANGE_G[1], positive=True),
    "overstrength": Column("overstrength", "number", low=OVERSTRENGTH_RANGE[0], high=OVERSTRENGTH_RANGE[1],
                           positive=True),
    "p_delta": Column("p_delta", "text", max_chars=10),
    "storey_stiffness": Column("storey_stiffness", "text", max_chars=2000),
    "pushover_slope_ratio": Column("pushover_slope_ratio", "number", low=PUSHOVER_SLOPE_RATIO_RANGE[0],
                                   high=PUSHOVER_SLOPE_RATIO_RANGE[1], positive=True),
    "lateral_stiffness_ratio": Column("lateral_stiffness_ratio", "number", low=LATERAL_STIFFNESS_RATIO_RANGE[0],
                                      high=LATERAL_STIFFNESS_RATIO_RANGE[1], positive=True),
    "storey_hardening_ratio": Column("storey_hardening_ratio", "number", low=STOREY_HARDENING_RATIO_RANGE[0],
                                     high=STOREY_HARDENING_RATIO_RANGE[1]),
    "brace_buckling": Column("brace_buckling", "text", max_chars=10),
    "storey_strength": Column("storey_strength", "text", max_chars=2000),
}


def _split_key(key: str, known: dict[str, Column]) -> tuple[str, str | None] | None:
    """``(name, unit suffix)`` of a key such as ``height_ft``; None when the key is unknown."""
    if key in known and known[key].dimension is None:
        return key, None
    for name, column in known.items():
        if column.dimension is not None and key.startswith(name + "_"):
            suffix = key[len(name) + 1:]
            if suffix in column.dimension.units:
                return name, suffix
        if name in _G_KEYS and key == f"{name}_g":
            return name, None
    return None


def _accepted(known: dict[str, Column]) -> list[str]:
    return [f"{n}_g" if n in _G_KEYS else column.header() for n, column in known.items()]


def _key_values(table, known: dict[str, Column], sheet: str, report,
                invalid: set | None = None) -> dict[str, tuple[object, int]]:
    """The sheet's keys, each parsed by its column, in canonical units: name -> (value, row). The names of
    rows whose value is reported as wrong are added to ``invalid``, so that no later check calls them missing."""
    key_header, value_header = table.headers.get("key"), table.headers.get("value")
    found: dict[str, tuple[object, int]] = {}
    for row in table.rows:
        if not row.ok("key", "value") or value_header is None or row.values["key"] is None:
            continue
        key = str(row.values["key"]).strip().lower()
        split = _split_key(key, known)
        if split is None:
            close = schema.suggest(key, _accepted(known))
            report.at(row.number, key_header, f"unknown key '{schema.clip(key, 40)}' in the {sheet} sheet"
                      + (f"; did you mean '{close}'?" if close else "."),
                      f"use one of {', '.join(_accepted(known))}.")
            continue
        name, suffix = split
        if name in found:
            report.at(row.number, key_header, f"'{name}' is given twice: in row {found[name][1]} and "
                      f"in row {row.number}.", "delete one of the two rows.")
            continue
        raw = row.values["value"]
        column = known[name]
        if schema.is_empty(raw):
            report.at(row.number, value_header, f"'{key}' has no value.", "type it, or delete the row.")
            if invalid is not None:
                invalid.add(name)
            continue
        try:
            value = schema.parse_cell(raw, column, suffix, f"the {sheet}")
        except CellError as error:
            report.at(row.number, value_header, f"'{key}': {error.message}", error.fix)
            if invalid is not None:
                invalid.add(name)
            continue
        found[name] = (value, row.number)
    return found


def read_site(table, folder: Path, report) -> SiteSheet | None:
    """The ``site`` sheet of a workbook in ``folder``, or None after reporting its problems.

    ``table`` is the sheet read against the ``key``/``value`` spec; ``report`` locates problems
    (:class:`assess.inventory.workbook.SheetReport`).
    """
    before = len(report.problems)
    invalid: set = set()
    values = _key_values(table, _SITE_KEYS, "site", report, invalid)
    value_header = table.headers.get("value")

    def at(name, message, fix):
        report.at(values[name][1], value_header, message, fix)

    out = {name: value for name, (value, _) in values.items()}
    code = _code(out.get("code", DEFAULT_CODE))
    if code is None:
        at("code", f"code {schema.quote(out['code'])} is not an edition the tool applies.",
           f"write {' or '.join(CODES)}.")
        code = DEFAULT_CODE
    site_class = None
    if "site_class" in out:
        site_class = str(out["site_class"]).strip().upper().replace("SITE CLASS", "").strip()
        allowed = SITE_CLASSES if code == "ASCE 7-22" else SITE_CLASSES_7_16
        if site_class == "F":
            at("site_class", "site class F needs a site response analysis (ASCE 7 §20.2.1); no "
               "coefficient gives its spectrum.", "give sds_g and sd1_g from the site response "
               "analysis instead of ss_g, s1_g and site_class.")
        elif site_class not in allowed:
            at("site_class", f"site class {schema.quote(out['site_class'])} is not one of {code}'s "
               f"({', '.join(allowed)}).", "write the site class letter(s) from the geotechnical report.")
    risk = str(out.get("risk_category", DEFAULT_RISK_CATEGORY)).strip().upper()
    risk = _ROMAN.get(risk, risk)
    if risk not in RISK_CATEGORIES:
        at("risk_category", f"risk category {schema.quote(out['risk_category'])} is not one of "
           f"{', '.join(RISK_CATEGORIES)}.", "write I, II, III or IV (ASCE 7 Table 1.5-1: a hospital is IV).")
    design = [k for k in ("sds", "sd1") if k in out]
    mapped = [k for k in ("ss", "s1") if k in out]
    if invalid & {"sds", "sd1", "ss", "s1", "site_class"}:
        pass  # a hazard value is given but wrong: its own cell says so; nothing is missing
    elif design and mapped:
        report.at(values[mapped[0]][1], table.headers.get("key"), "the site sheet gives both design "
                  f"values ({', '.join(design)}) and mapped values ({', '.join(mapped)}).",
                  "keep one set: sds_g and sd1_g (from a hazard lookup), or ss_g, s1_g and site_class.")
    elif design and len(design) < 2:
        missing = ({"sds", "sd1"} - set(design)).pop()
        report.at(values[design[0]][1], table.headers.get("key"), f"the site sheet gives {design[0]}_g "
                  f"without {missing}_g.", f"add a row {missing}_g (both come from the site's hazard lookup).")
    elif design and not CORNER_PERIOD_RANGE_S[0] <= out["sd1"] / out["sds"] <= CORNER_PERIOD_RANGE_S[1]:
        at("sd1", f"sd1_g {out['sd1']:g} over sds_g {out['sds']:g} puts the design spectrum's corner T_s = "
           f"S_D1/S_DS at {out['sd1'] / out['sds']:.3g} s, outside {CORNER_PERIOD_RANGE_S[0]:g} to "
           f"{CORNER_PERIOD_RANGE_S[1]:g} s (a mapped site's T_s is about 0.15 to 2 s).",
           "check both values: each in g, the design (not the mapped MCE_R) values, from the same hazard lookup.")
    elif mapped and (len(mapped) < 2 or "site_class" not in out):
        missing = sorted({"ss", "s1", "site_class"} - set(mapped) - set(out))
        report.at(values[mapped[0]][1], table.headers.get("key"), f"the site sheet gives "
                  f"{', '.join(mapped)} without {', '.join(missing)}.",
                  "add the missing rows: ss_g, s1_g and site_class go together (the site class sets the "
                  "site coefficients).")
    if not design and not mapped and "uhs" not in out and not invalid & {"sds", "sd1", "ss", "s1", "uhs"}:
        report("the site sheet gives no hazard: neither sds_g and sd1_g, nor ss_g, s1_g and "
               "site_class, nor a uniform-hazard spectrum (uhs).",
               "add the site's design values (sds_g, sd1_g) from a hazard lookup, or delete the sheet.",
               row=1)
    paths = {}
    for name, kind in (("uhs", "file"), ("records", "folder")):
        if name in out:
            path = _inside(folder, out[name])
            if path is None:
                at(name, f"{name} {schema.quote(out[name])} lies outside the workbook's folder.",
                   f"move the {kind} into the workbook's folder and give its path relative to it.")
            elif kind == "file" and not path.is_file():
                at(name, f"{name} {schema.quote(out[name])} is not a file.",
                   "give the path of the OpenQuake export, relative to the workbook's folder.")
            elif kind == "folder" and not path.is_dir():
                at(name, f"records {schema.quote(out[name])} is not a folder.",
                   "give the folder of ground-motion records, relative to the workbook's folder.")
            else:
                paths[name] = str(path)
    scaling = str(out.get("records_scaling", "amplitude")).strip().lower()
    if scaling not in RECORDS_SCALINGS:
        at("records_scaling", f"records_scaling {schema.quote(out['records_scaling'])} is not "
           + " or ".join(RECORDS_SCALINGS) + ".", "write amplitude (each record scaled by one factor, ASCE 7-22 "
           "§16.2.3.2) or matched (each record's spectrum matched to the target, §16.2.3.3), or delete the row.")
    elif "records_scaling" in out and "records" not in out and "records" not in invalid:
        at("records_scaling", "records_scaling says how the records of a records folder are fitted to the "
           "target, and the sheet names no records folder.", "add a row records (the folder of ground-motion "
           "records), or delete this row: the synthetic motions are matched to the target already.")
    if len(report.problems) > before:
        return None
    return SiteSheet(code=code, sds_g=out.get("sds"), sd1_g=out.get("sd1"), ss_g=out.get("ss"),
                     s1_g=out.get("s1"), site_class=site_class, tl_s=out.get("tl"),
                     risk_category=risk, uhs_path=paths.get("uhs", ""), oq_site=out.get("oq_site", ""),
                     records_folder=paths.get("records", ""), records_scaling=scaling,
                     suite_size=int(out["suite_size"]) if "suite_size" in out else None,
                     rows={name: row for name, (_, row) in values.items()}, sheet=table.title)


def read_building(table, report) -> BuildingSheet | None:
    """The ``building`` sheet, or None after reporting its problems."""
    before = len(report.problems)
    invalid: set = set()  # keys given with a value refused at its cell: not missing
    values = _key_values(table, _BUILDING_KEYS, "building", report, invalid)
    value_header, key_header = table.headers.get("value"), table.headers.get("key")
    out = {name: value for name, (value, _) in values.items()}
    if "storeys" not in out and "storeys" not in invalid:
        report("the building sheet has no 'storeys'.", "add a row storeys with the number of storeys "
               "above ground (floors are numbered 0, the ground, to storeys, the roof).", row=1)
    if "height" in out and "storey_height" in out:
        report.at(values["storey_height"][1], key_header, "the building sheet gives both height and "
                  "storey_height.", "keep one: height_m (roof above ground) or storey_height_m (uniform).")
    elif not {"height", "storey_height"} & (set(out) | invalid):
        report("the building sheet has no height.", "add height_m (the roof above the ground floor) or "
               "storey_height_m (when every storey is as high).", row=1)
    system = str(out.get("system", "other")).strip().lower()
    if system not in SYSTEMS:
        close = schema.suggest(system, list(SYSTEMS))
        report.at(values["system"][1], value_header, f"system {schema.quote(out['system'])} is not one of "
                  "the lateral systems" + (f"; did you mean '{close}'?" if close else "."),
                  f"write one of {', '.join(SYSTEMS)} (ASCE 7 Table 12.8-2).")
    response = None
    if "response" in out:
        response = str(out["response"]).strip().lower()
        if response not in RESPONSES:
            close = schema.suggest(response, list(RESPONSES))
            report.at(values["response"][1], value_header, f"response {schema.quote(out['response'])} is not "
                      + " or ".join(RESPONSES) + (f"; did you mean '{close}'?" if close else "."),
                      "write yielding (a stick of storey springs that yield) or elastic (the building's elastic "
                      "modes), or delete the row.")
    p_delta = False
    if "p_delta" in out:
        word = str(out["p_delta"]).strip().lower()
        if word not in _YES + _NO:
            report.at(values["p_delta"][1], value_header, f"p_delta {schema.quote(out['p_delta'])} is not "
                      "yes or no.", "write yes (the gravity loads' P-Delta effect on the yielding storeys) or no.")
        p_delta = word in _YES
    buckling = False
    if "brace_buckling" in out:
        word = str(out["brace_buckling"]).strip().lower()
        row = values["brace_buckling"][1]
        if word not in _YES + _NO:
            report.at(row, value_header, f"brace_buckling {schema.quote(out['brace_buckling'])} is not yes or no.",
                      "write yes (the braces buckle: each storey its two braces, one pulled and one pushed) or no.")
        buckling = word in _YES
        if system in SYSTEMS and system != "braced frame":
            report.at(row, key_header, f"brace_buckling is given but the system is {system}: only a braced frame's "
                      "storeys are braces.", "delete the brace_buckling row, or write braced frame in system.")
        elif buckling and "pushover_slope_ratio" in out:
            report.at(row, key_header, "brace_buckling is yes and pushover_slope_ratio is given: α is found by "
                      "pushing over storeys that harden after yield, and buckling braces' storeys lose strength.",
                      "delete the pushover_slope_ratio row (give α in lateral_stiffness_ratio where known), or "
                      "write no in brace_buckling.")
    if response == "elastic":
        for key in ("yield_base_shear", "overstrength", "p_delta", "storey_hardening_ratio", "brace_buckling",
                    "storey_strength"):
            if key in out:
                name = "yield_base_shear_g" if key == "yield_base_shear" else key
                report.at(values[key][1], key_header, f"{name} is given but response is elastic: the elastic "
                          "modes have no strength, so it would be ignored.",
                          f"delete the {name} row, or write yielding in response (row {values['response'][1]}).")
        if "pushover_slope_ratio" in out:
            report.at(values["pushover_slope_ratio"][1], key_header, "pushover_slope_ratio is given but response is "
                      "elastic: α is found from it by pushing over the yielding stick, at the pushover's strength, "
                      "which the elastic modes do not have.", "write yielding in response (row "
                      f"{values['response'][1]}) with yield_base_shear_g, or give α in lateral_stiffness_ratio and "
                      "delete the pushover_slope_ratio row.")
    if "storeys" in out and too_tall_to_yield(out["storeys"]) and response != "elastic":
        beyond = (f"the building has {int(out['storeys'])} storeys: the yielding model takes at most "
                  f"{MAX_YIELDING_STOREYS} (its cost grows with the cube of the storeys: 6 to 28 s a ground motion at "
                  "48, by system), and beyond that the building's elastic modes answer.")
        deleted = f"above {MAX_YIELDING_STOREYS} storeys the elastic modes answer, and they"
        # what asks for the yielding model: key, whether it asks, its words, the fix
        for key, asks, said, fix in (
                ("response", response == "yielding", "response is yielding",
                 "write elastic in response (the elastic modes answer any height)"),
                ("yield_base_shear", "yield_base_shear" in out, "yield_base_shear_g is given",
                 f"delete the yield_base_shear_g row: {deleted} have no strength."),
                ("overstrength", "overstrength" in out, "overstrength is given",
                 f"delete the overstrength row: {deleted} have no strength."),
                ("p_delta", p_delta, "p_delta is given", f"delete the p_delta row: {deleted} carry no P-Delta."),
                ("storey_hardening_ratio", "storey_hardening_ratio" in out, "storey_hardening_ratio is given",
                 f"delete the storey_hardening_ratio row: {deleted} do not yield."),
                ("brace_buckling", buckling, "brace_buckling is yes", f"delete the brace_buckling row: {deleted} do "
                 "not buckle."),
                ("storey_strength", "storey_strength" in out, "storey_strength is given",
                 f"delete the storey_strength row: {deleted} have no strength."),
                ("pushover_slope_ratio", "pushover_slope_ratio" in out, "pushover_slope_ratio is given",
                 f"delete the pushover_slope_ratio row ({deleted} take α from lateral_stiffness_ratio).")):
            if asks:
                report.at(values[key][1], value_header if key == "response" else key_header, f"{said} but {beyond}",
                          fix)
    if "yield_base_shear" in out and "overstrength" in out:
        report.at(values["overstrength"][1], key_header, "the building sheet gives both yield_base_shear_g and "
                  "overstrength: the overstrength multiplies the code's design strength, which a given base "
                  "shear at yield replaces.", "keep yield_base_shear_g (from a pushover or an evaluation) or "
                  "overstrength, not both.")
    if "pushover_slope_ratio" in out and response != "elastic":
        _check_pushover_slope(out, values, system, report, key_header)
    profiles = {}
    for key in ("storey_stiffness", "storey_strength"):
        if key in out and "storeys" in out:
            profiles[key], problem = parse_storey_profile(out[key], int(out["storeys"]), key)
            if problem is not None:
                report.at(values[key][1], value_header, *problem)
    if len(report.problems) > before:
        return None
    storeys = int(out["storeys"])
    height_m = out["height"] if "height" in out else out["storey_height"] * storeys
    if not 2.0 * storeys <= height_m <= 10.0 * storeys:
        where = values["height" if "height" in out else "storey_height"][1]
        report.at(where, value_header, f"a roof {height_m:.3g} m above the ground over {storeys} storeys "
                  f"is {height_m / storeys:.3g} m a storey; storeys are 2 to 10 m high.",
                  "check the unit in the key (height_m, height_ft) and the number of storeys.")
        return None
    approximate = float(approximate_period(height_m, system))
    if "period" in out and out["period"] < approximate / PERIOD_BELOW_APPROXIMATE:
        report.at(values["period"][1], value_header, f"a T1 of {out['period']:g} s is below 1/"
                  f"{PERIOD_BELOW_APPROXIMATE:g} of ASCE 7's approximate period T_a = {approximate:.2g} s of a "
                  f"{system} {height_m:.3g} m high (Eq. 12.8-7): stiffer than buildings are.",
                  "write the fundamental period in seconds (not a frequency), or delete the row to take T_a.")
        return None
    return BuildingSheet(storeys=storeys, height_m=float(height_m), system=system,
                         period_s=out.get("period"), damping=float(out.get("damping", DEFAULT_DAMPING)),
                         response=response, yield_base_shear_g=out.get("yield_base_shear"),
                         overstrength=out.get("overstrength"), p_delta=p_delta,
                         storey_stiffness=profiles.get("storey_stiffness"),
                         storey_strength=profiles.get("storey_strength"),
                         lateral_stiffness_ratio=out.get("lateral_stiffness_ratio"),
                         pushover_slope_ratio=out.get("pushover_slope_ratio"),
                         storey_hardening_ratio=out.get("storey_hardening_ratio"), brace_buckling=buckling,
                         rows={name: row for name, (_, row) in values.items()}, sheet=table.title)


def _check_pushover_slope(out: dict, values: dict, system: str, report, key_header) -> None:
    """Report where the sheet's ``pushover_slope_ratio`` cannot give α: with α given, without the pushover's
    strength, or for a system whose slope after yield α does not set."""
    row = values["pushover_slope_ratio"][1]
    if "lateral_stiffness_ratio" in out:
        report.at(row, key_header, "the building sheet gives both lateral_stiffness_ratio and pushover_slope_ratio: "
                  "the pushover's slope is used to find α, which lateral_stiffness_ratio gives already.",
                  "keep lateral_stiffness_ratio (α from the building's model) or pushover_slope_ratio, not both.")
    elif system in SYSTEMS and system not in PUSHOVER_ALPHA_SYSTEMS:
        why = ("a wall yields at its base, where its slope after yield is its hinge's hardening, not α" if
               system == "shear wall" else "its stick is a shear stick, whose slope after yield is its springs' own")
        report.at(row, key_header, f"pushover_slope_ratio finds α for frames and braced frames only: for a {system} "
                  f"{why}.", "delete the pushover_slope_ratio row, and give lateral_stiffness_ratio where the "
                  "building's α is known.")
    elif "yield_base_shear" not in out:
        report.at(row, key_header, "pushover_slope_ratio is given without yield_base_shear_g: α is found by pushing "
                  "over the model at the pushover's strength.", "add yield_base_shear_g from the same pushover (its "
                  "base shear at the first storey's yield, over the weight), or delete the pushover_slope_ratio row.")


#: What each storey profile of the building sheet gives, in words: (the values, the most, the least, the storey the
#: model does not assess (a soft or weak one), where it comes from in a model).
_PROFILE_WORDS = {
    "storey_stiffness": ("stiffnesses", "stiffest", "softest", "soft", "a model's storey stiffness table"),
    "storey_strength": ("strengths", "strongest", "weakest", "weak",
                        "a stick model's storey springs' yield shears, or each storey's design shear over its "
                        "demand-capacity ratio"),
}


def parse_storey_profile(text, storeys: int, key: str = "storey_stiffness"):
    """``(values, None)`` from the building sheet's ``storey_stiffness`` or ``storey_strength`` (``key``), or
    ``(None, (message, fix))``.

    The value is ``uniform`` or one positive number per storey, the first storey to the roof, separated by
    commas or semicolons: the storeys' stiffnesses (strengths) in any unit (a model's storey stiffness table),
    only their ratios count (the building's T_1, its strength at yield, sets the scale).

    >>> parse_storey_profile("1, 0.9; 0.78", 3)
    ((1.0, 0.9, 0.78), None)
    >>> parse_storey_profile("uniform", 2)
    ((1.0, 1.0), None)
    >>> parse_storey_profile("1, 0.9", 3, "storey_strength")[1][0]
    'storey_strength gives 2 values for 3 storeys.'
    """
    what, most, least, weak, source = _PROFILE_WORDS[key]
    how = (f"write {storeys} positive number{'s' if storeys > 1 else ''}, the storeys' {what} from the "
           f"first storey to the roof separated by commas (e.g. 1, 0.9, 0.8 from {source}; only their ratios "
           "count), or uniform, or delete the row for the system's "
           + ("design profile." if key == "storey_stiffness" else "rule."))
    word = str(text).strip().lower()
    if word == "uniform":
        return (1.0,) * storeys, None
    parts = [part.strip() for part in re.split(r"[,;]", word)]
    try:
        values = tuple(float(part) for part in parts)
    except ValueError:
        bad = next(part for part in parts if not _is_number(part))
        return None, (f"{key} {schema.quote(text)}: {schema.quote(bad)} is not a number.", how)
    if len(values) != storeys:
        return None, (f"{key} gives {len(values)} value{'s' if len(values) != 1 else ''} for "
                      f"{storeys} storey{'s' if storeys != 1 else ''}.", how)
    if not all(v > 0.0 and v < float("inf") for v in values):
        return None, (f"{key} {schema.quote(text)} has a value that is not greater than 0.", how)
    if max(values) > STOREY_STIFFNESS_SPREAD * min(values):
        return None, (f"{key} {schema.quote(text)}: the {most} storey is {max(values) / min(values):.3g} "
                      f"times the {least}; the stick takes at most {STOREY_STIFFNESS_SPREAD:g} times.",
                      f"check the values (one per storey, the same unit for all); a storey that {weak} is a {weak} "
                      "storey, which this model of the building does not assess.")
    return values, None


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def check_building_strength(table, building: BuildingSheet, site: SiteSheet | None, report) -> None:
    """Report ``response: yielding`` where nothing gives the storeys' strength, at the response cell; and, where the
    sheet names no ``response`` and the building is elastic for want of a strength, each key only the yielding stick
    uses (``overstrength``, ``p_delta`` yes, ``storey_hardening_ratio``, ``brace_buckling`` yes,
    ``storey_strength``) at its key cell.

    The yielding stick's strength is ``yield_base_shear_g``, else the code's design from the site sheet's
    design values (S_DS, S_D1 or S_S, S_1 and the site class); a site given only by a uniform-hazard
    spectrum, or no site sheet, gives no design. ``table`` is the building sheet as read, ``report`` its
    :class:`~assess.inventory.workbook.SheetReport`.
    """
    if building.yield_base_shear_g is not None or (site is not None and site.has_design_values):
        return
    if building.response is None and not building.too_tall_to_yield:  # elastic by default: say what goes unused
        for key, asks in (("overstrength", building.overstrength is not None), ("p_delta", building.p_delta),
                          ("storey_hardening_ratio", building.storey_hardening_ratio is not None),
                          ("brace_buckling", building.brace_buckling),
                          ("storey_strength", building.storey_strength is not None)):
            if asks:
                report.at(building.rows[key], table.headers.get("key"), f"{key} is given but nothing gives the "
                          "storeys' strength (no yield_base_shear_g, and the site sheet no design values), so the "
                          "building answers through its elastic modes, which do not yield: it would be ignored.",
                          "add yield_base_shear_g (the base shear at yield over the weight, from a pushover or an "
                          f"evaluation) or the site's design values to the site sheet, or delete the {key} row.")
    if building.response != "yielding":
        return
    report.at(building.rows["response"], table.headers.get("value"),
              "response is yielding but nothing gives the storeys' strength: the building sheet has no "
              "yield_base_shear_g and the site sheet no design values (sds_g and sd1_g, or ss_g, s1_g and "
              "site_class) for the code's design.",
              "add yield_base_shear_g (the base shear at yield over the weight, from a pushover or an "
              "evaluation), or the site's design values to the site sheet, or write elastic in response.")


def check_item_floors(table, building: BuildingSheet, report) -> None:
    """Report every item whose ``floor`` the building sheet does not have, at its cell.

    The building has floors 0 (the ground floor) to ``storeys`` (the roof) and no basement: an item
    above the roof or below the ground floor would get no motion from it. The workbook's floor numbers
    count the ground floor 0 whatever ``floor_numbering`` says (docs/workbook.md). ``table`` is the
    equipment sheet read against its spec, ``report`` its :class:`~assess.inventory.workbook.SheetReport`.
    """
    header = table.headers.get("floor")
    has = (f"the building sheet has floors 0 (the ground floor) to {building.storeys} (the roof: storeys "
           f"{building.storeys}) and no basement")
    for row in table.rows:
        floor = row.values.get("floor")
        if not row.ok("floor") or floor is None or 0 <= int(floor) <= building.storeys:
            continue
        item = row.values.get("id")
        what = f"item '{item}'" if item is not None else "the item"
        if int(floor) > building.storeys:
            message = (f"{what} is on floor {int(floor)}, above the roof: {has}. The workbook counts the "
                       "ground floor 0 whatever floor_numbering says.")
            fix = (f"write the item's floor counting the ground floor 0 (the roof is {building.storeys}; "
                   "under floor_numbering ground_1 the report labels it one higher), or correct storeys in "
                   "the building sheet.")
        else:
            message = f"{what} is on floor {int(floor)}, below the ground floor: {has}."
            fix = ("correct the floor, counting the ground floor 0; an item in a basement moves about as the "
                   "ground does: write floor 0 for it (and its basement in the room column).")
        report.at(row.number, header, message, fix)


def _code(text) -> str | None:
    """The edition named by ``text`` (``ASCE 7-22``, ``asce7-22``, ``7-16``), None when unknown."""
    compact = re.sub(r"[\s_]", "", str(text)).upper().replace("ASCE", "")
    for code in CODES:
        if compact in (code.replace("ASCE ", ""), code.replace("ASCE ", "").replace("-", "")):
            return code
    return None


def _inside(folder: Path, relative: str) -> Path | None:
    """``relative`` resolved against ``folder``; None when it leads outside it."""
    base = folder.resolve()
    path = (base / relative).resolve()
    return path if path == base or base in path.parents else None


__all__ = ["SiteSheet", "BuildingSheet", "read_site", "read_building", "check_building_strength",
           "check_item_floors", "CODES", "SYSTEMS", "RESPONSES",
           "SITE_CLASSES", "RISK_CATEGORIES"]
