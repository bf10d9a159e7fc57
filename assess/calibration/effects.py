"""The effects a calibration may switch on: each a real change of the engine's model.

Every effect changes one physical ingredient of the block model of
:mod:`assess.mechanics.block` with one or two parameters, each with bounds and
a neutral value (the value at which the effect changes nothing, or the closest
the effect comes to that; None for ``restitution``, whose neutral is Housner's
e, different for every item). :data:`EFFECTS` lists them by name (docs/calibration.md):

``none``
    The model as the workbook declares it.
``friction_scale``
    μ and μ_s both × k. Konstantinidis & Makris [1] (section 5, Table 3)
    found the best-fit μ of shake-table tests (0.13/0.17/0.20) well below the
    slow-pull μ (0.23/0.28/0.31): k ≈ 0.6.
``static_friction``
    μ_s = r·μ, r ≥ 1 (sticking needs more than sliding). r = 1 is neutral
    for the usual workbook that declares no μ_s.
``restitution``
    The angular-velocity ratio e at a rocking impact, in [0, 1], instead of
    Housner's value (:attr:`Block.restitution`). Acts on rocking items only.
``input_scale``
    The floor motion × s (the table played a different amplitude from the
    one it was asked for).
``velocity_friction``
    μ falls with slip velocity from μ_max = μ (the slow-pull value the
    workbook declares) to μ_min = f·μ, at rate ``rate_s_m``
    (:func:`assess.mechanics.interface.velocity_friction_response`). That
    kernel is a sliding-only solver, so it is used for items that cannot
    uplift (μ_s < b/h, :func:`assess.mechanics.gateway.pure_sliding_proved`);
    items that can uplift keep the engine's normal model under this effect.
``interface_elasticity``
    A compliant (elastic–perfectly-plastic) interface of yield displacement
    u_y before slip (:func:`assess.mechanics.interface.elastic_interface_response`),
    with the same restriction to items that cannot uplift.
``foot_inset``
    The item stands on feet inset by a fraction d of its half-width, so it
    rocks about feet at b(1 − d) (``Block.foot_inset_m``): α, R and p are
    those about a foot, the moment of inertia stays that of the whole box.

Every effect's θmax/α is θmax over α of the item's **declared** box,
atan(b/h) (:func:`declared_alpha_rad`), as the measured one is (docs/workbook.md, the measured tests):
with feet the solvers divide by α of the feet, and the prediction is
brought back to the declared α.

The two interface effects need :mod:`assess.mechanics.interface`; when it is
not installed, :func:`available_effects` leaves them out.

Every prediction is a run of the engine's gateway (a ``response`` run,
:func:`assess.mechanics.gateway.run_responses`), the tests of one grid point
in one batch (:func:`assess.calibration.fit.predict_cases`).

Which base direction a test shook comes with the test (see
:mod:`assess.calibration.measured`); the effects take the half-width of that
direction.

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Experimental and analytical
   studies on the response of freestanding laboratory equipment to earthquake
   shaking. Earthquake Eng. Struct. Dyn. 39(10):1097-1118 (section 5, Table 3).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from dataclasses import fields as dataclass_fields
from typing import Callable, Mapping, NamedTuple

import numpy as np

from assess.hazard.records import Record
from assess.mechanics.block import Block
from assess.mechanics.geometry import slenderness
from assess.mechanics.gateway import BlockOnInterface, SlidingInterface, run_responses, solver_installed

INTERFACE_MODULE = "assess.mechanics.interface"


class Prediction(NamedTuple):
    """The peaks a model predicts for one test."""

    sliding_max_m: float
    theta_max_over_alpha: float
    overturned: bool
    mode: str


@dataclass(frozen=True)
class Parameter:
    """One parameter of an effect: bounds, neutral value and whether it is searched on a log scale."""

    name: str
    lower: float
    upper: float
    neutral: float | None
    unit: str = "-"
    log: bool = False
    #: What it is, in words (the report's rows).
    label: str = ""
    #: Which tests can fix it (said when these cannot).
    determined_by: str = "only tests whose peaks depend on it can fix it"

    def grid(self, count: int) -> np.ndarray:
        """``count`` values from lower to upper (geometric when ``log``), and the neutral value."""
        values = (np.geomspace if self.log else np.linspace)(self.lower, self.upper, count)
        return np.unique(values if self.neutral is None else np.append(values, self.neutral))


@dataclass(frozen=True)
class Effect:
    """A change of the model: ``predict(item, half_width_m, motion, parameters) -> Prediction``."""

    name: str
    description: str
    parameters: tuple[Parameter, ...]
    predict: Callable[[Mapping, float, Record, Mapping[str, float]], Prediction]
    requires: str | None = None

    @property
    def neutral(self) -> dict[str, float]:
        return {p.name: p.neutral for p in self.parameters}

    def available(self) -> bool:
        """Whether the module the effect needs is installed."""
        return self.requires is None or solver_installed(self.requires)

    def model(self, item: Mapping, half_width_m: float, motion: Record,
              parameters: Mapping[str, float]) -> tuple[Block, Record]:
        """The block and the floor motion that ``predict`` simulates for one test."""
        return (calibrated_block(item_block(item, half_width_m), self.name, parameters),
                calibrated_motion(motion, self.name, parameters))


def half_width_of(item: Mapping, direction: int) -> float:
    """b [m] of ``item`` when shaken in ``direction`` (1: along the width, 2: along the depth)."""
    return float(item["width_m"] if int(direction) == 1 else item["depth_m"]) / 2.0


def item_block(item: Mapping, half_width_m: float, **changes) -> Block:
    """The block of ``item`` (an equipment row) of half-width b; ``changes`` override its fields.

    μ_s is raised to μ where a change would leave it below.
    """
    values = dict(half_width_m=half_width_m, cg_height_m=float(item["cg_height_m"]),
                  height_m=float(item["height_m"]), mu=float(item["mu"]),
                  mu_static=float(item.get("mu_static", item["mu"])))
    values.update(changes)
    values["mu_static"] = max(values["mu_static"], values["mu"])
    return Block(**values)


def declared_alpha_rad(block: Block) -> float:
    """α = atan(b/h) of the item's declared box [rad], whatever it stands on (as measured: docs/workbook.md).

    A measured θmax/α is divided by this α; an effect may change the points
    the block pivots on (``foot_inset``), never the α a rotation is read against.

    >>> footed = Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.7, foot_inset_m=0.09)
    >>> round(declared_alpha_rad(footed), 6), round(footed.alpha_rad, 6)
    (0.291457, 0.206992)
    """
    return float(slenderness(block.half_width_m, block.cg_height_m))


def theta_over_declared_alpha(response_theta_max_over_alpha, block: Block) -> float:
    """A solver's θmax/α (α of the pivots it rocked on) as θmax over α of the declared box [-]."""
    return float(response_theta_max_over_alpha) * block.alpha_rad / declared_alpha_rad(block)


def prediction(block: Block, response) -> Prediction:
    """The peaks of the engine's ``response`` of ``block``, θmax over α of the declared box (as measured,
    docs/calibration.md) for every effect."""
    return Prediction(float(response.sliding_max_m), theta_over_declared_alpha(response.theta_max_over_alpha, block),
                      bool(response.overturned), response.mode)


def calibrated_block(block: Block, effect: str, parameters: Mapping[str, float]) -> Block:
    """``block`` with ``effect`` switched on at ``parameters``: the one definition of every effect.

    The calibration's predictions (:func:`predict`) and the assessment under
    ``--calibration`` (:mod:`assess.calibration.apply`) both call it, so the
    main job simulates what ``assess calibrate`` fitted. ``input_scale``
    changes the motion, not the block (:func:`calibrated_motion`).

    >>> block = Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2, mu_static=0.25)
    >>> scaled = calibrated_block(block, "friction_scale", {"k": 0.5})
    >>> scaled.mu, scaled.mu_static
    (0.1, 0.125)
    >>> calibrated_block(block, "static_friction", {"r": 2.0}).mu_static
    0.4
    >>> round(calibrated_block(block, "foot_inset", {"d": 0.2}).contact_half_width_m, 12)
    0.24
    """
    if effect in ("none", "input_scale"):
        return block
    if effect == "friction_scale":
        k = float(parameters["k"])
        return replace(block, mu=k * block.mu, mu_static=k * block.mu_static)
    if effect == "static_friction":
        return replace(block, mu_static=max(float(parameters["r"]) * block.mu, block.mu))
    if effect == "restitution":  # None: Housner's value (a calibration that could not determine e)
        e = parameters["e"]
        return replace(block, restitution=None if e is None else float(e))
    if effect == "foot_inset":
        return replace(block, foot_inset_m=float(parameters["d"]) * block.half_width_m)
    if effect == "velocity_friction":
        interface = SlidingInterface(low_speed_factor=float(parameters["f"]), rate_s_m=float(parameters["rate_s_m"]))
    elif effect == "interface_elasticity":
        interface = SlidingInterface(yield_displacement_m=float(parameters["yield_displacement_m"]))
    else:
        raise ValueError(f"unknown effect {effect!r}; known: {list(EFFECTS)}")
    fields = {f.name: getattr(block, f.name) for f in dataclass_fields(Block)}
    return BlockOnInterface(**fields, interface=interface)


def calibrated_motion(motion: Record, effect: str, parameters: Mapping[str, float]) -> Record:
    """The floor motion with ``effect`` switched on: × s for ``input_scale``, unchanged otherwise."""
    return motion.scaled(float(parameters["s"])) if effect == "input_scale" else motion


def _predictor(effect: str):
    """``predict(item, half_width_m, motion, parameters)`` of one effect (see :class:`Effect`)."""
    def predict(item, half_width_m, motion, parameters):
        block, motion = EFFECTS[effect].model(item, half_width_m, motion, parameters)
        response, = run_responses([(block, motion.accel_g, motion.dt_s)])
        return prediction(block, response)
    predict.__name__ = f"predict_{effect}"
    return predict


#: Every effect, by name, in the order the report lists them.
EFFECTS: dict[str, Effect] = {e.name: e for e in [
    Effect("none", "the model as declared", (), _predictor("none")),
    Effect("friction_scale", "μ and μ_s × k",
           (Parameter("k", 0.3, 1.5, 1.0, label="factor k on μ and μ_s",
                      determined_by="k acts only on tests in which a specimen slides or comes close to it"),),
           _predictor("friction_scale")),
    Effect("static_friction", "μ_s = r·μ",
           (Parameter("r", 1.0, 3.0, 1.0, label="ratio r of static to kinetic μ",
                      determined_by="r acts only on tests whose floor acceleration reaches μ"),),
           _predictor("static_friction")),
    Effect("restitution", "rocking impact restitution e (instead of Housner's)",
           (Parameter("e", 0.0, 1.0, None, label="restitution e at a rocking impact",
                      determined_by="e acts only at rocking impacts, so only tests in which a specimen "
                      "rocks back onto its other edge can fix it"),),
           _predictor("restitution")),
    Effect("input_scale", "floor motion × s",
           (Parameter("s", 0.5, 2.0, 1.0, log=True, label="factor s on the floor motion",
                      determined_by="no specimen's peaks change with the motion's amplitude"),),
           _predictor("input_scale")),
    Effect("velocity_friction", "kinetic μ rises with slip velocity from f·μ (slow) to μ (fast); breakaway at μ_s",
           (Parameter("f", 0.3, 1.0, 1.0, label="low-speed friction factor f",
                      determined_by="f acts only on specimens that slide without uplifting"),
            Parameter("rate_s_m", 1.0, 100.0, 10.0, unit="s/m", log=True, label="rate a of the rise of μ with speed",
                      determined_by="the rate acts only on specimens that slide without uplifting, and "
                      "only where f is below 1")),
           _predictor("velocity_friction"), requires=INTERFACE_MODULE),
    Effect("interface_elasticity", "elastic interface of yield displacement u_y before slip",
           (Parameter("yield_displacement_m", 0.0005, 0.05, 0.0005, unit="m", log=True,
                      label="yield displacement u_y of the interface",
                      determined_by="u_y acts only on specimens that slide without uplifting"),),
           _predictor("interface_elasticity"), requires=INTERFACE_MODULE),
    Effect("foot_inset", "rocks about feet inset by d·b",
           (Parameter("d", 0.0, 0.6, 0.0, label="foot inset d, as a fraction of the half-width",
                      determined_by="d acts only on tests in which a specimen uplifts or comes close to it"),),
           _predictor("foot_inset")),
]}


def available_effects(names=None) -> list[Effect]:
    """The effects (all, or those named) whose solvers are installed, ``none`` first."""
    chosen = list(EFFECTS) if names is None else ["none"] + [n for n in names if n != "none"]
    unknown = [n for n in chosen if n not in EFFECTS]
    if unknown:
        raise ValueError(f"unknown effects {unknown}; known: {list(EFFECTS)}")
    return [EFFECTS[n] for n in chosen if EFFECTS[n].available()]
