"""The stripes of a hazard curve through a yielding building skip the stick where it cannot yield.

The stick is linear from rest until its first spring (or a wall's base hinge) yields, whatever its springs'
law: under a copy of a ground history weaker than one that yielded no storey, no storey yields and every
drift scales with the copy. :class:`assess.building.yielding.ElasticBound` keeps, per ground history, the
strongest copy that stayed elastic, so that the weaker stripes' floors come from the elastic route without the
stick. Checked here against the stick itself run at every scale: the same floors bit for bit, the drifts in
the ratio of the scales (the linear closed form), and fewer runs of the stick.
"""
import numpy as np
import pytest

from assess.building import yielding as yielding_module
from assess.building.modes import building_modes
from assess.fragility.ground_stripes import stripe_histories
from assess.hazard.records import Record

#: PGAs [g] of the stripes, strongest first as the curve passes them: the weakest leave a 4-storey frame
#: designed for S_DS 1.0 g elastic under both ground histories, the strongest yield it.
STRIPES_G = (2.0, 0.9, 0.4, 0.12, 0.05, 0.02)


def _ground():
    t = np.arange(0.0, 12.0, 0.01)
    one = Record(np.sin(2 * np.pi * t / 0.7) * np.exp(-((t - 4.0) / 2.0) ** 2), 0.01, "pulse")
    two = Record(np.sin(2 * np.pi * t / 0.35) * np.exp(-((t - 5.0) / 3.0) ** 2) * 0.8, 0.01, "burst")
    return [(one, one), (two, two)]


@pytest.fixture(params=["steel moment frame", "shear wall"])
def building(request):
    system = request.param
    modes = building_modes(4, 3.5, system=system, period_s=0.5)
    return yielding_module.yielding_building(modes, system, sds_g=1.0, sd1_g=0.6)


def test_weaker_copies_of_an_elastic_pass_skip_the_stick_and_give_its_floors(building, monkeypatch):
    ground = _ground()
    yielding_module.forget()
    plain = {x: stripe_histories(building, ground, x, [0, 2, 4]) for x in STRIPES_G}
    # each stripe's pass with the stick run on every copy, and whether the stick yielded under each
    runs = []
    kernel = (yielding_module.hinged_wall_response if isinstance(building.stick, yielding_module.HingedWall)
              else yielding_module.yielding_response)
    name = kernel.__name__

    def counted(stick, ground_accel_g, dt_s):
        runs.append(float(np.max(np.abs(ground_accel_g))))
        return kernel(stick, ground_accel_g, dt_s)

    monkeypatch.setattr(yielding_module, name, counted)
    yielding_module.forget()
    bound = yielding_module.ElasticBound()
    bounded = {x: stripe_histories(building, ground, x, [0, 2, 4], bound=bound) for x in STRIPES_G}
    for x in STRIPES_G:
        assert bounded[x][1] == plain[x][1]  # the drift flags
        for floor in (0, 2, 4):
            for (w, d), (w0, d0) in zip(bounded[x][0][floor], plain[x][0][floor]):
                assert w.accel_g.tobytes() == w0.accel_g.tobytes() and d.accel_g.tobytes() == d0.accel_g.tobytes()
    # the strongest stripe yields the building, the weakest run no stick: fewer runs than copies
    monkeypatch.setattr(yielding_module, name, kernel)
    strongest = [yielding_module.stick_history(building, w.accel_g * (STRIPES_G[0] / np.max(np.abs(w.accel_g))),
                                               w.dt_s) for w, _ in ground]
    assert not any(h.elastic for h in strongest)
    assert min(runs) > STRIPES_G[-1] and len(runs) < len(STRIPES_G) * len(ground)


def test_a_weaker_elastic_history_has_the_sticks_drifts_in_the_ratio_of_the_scales(building):
    (one, _), _ = _ground()
    yielding_module.forget()
    stronger = yielding_module.stick_history(building, 0.05 * one.accel_g, one.dt_s)
    assert stronger.elastic
    bound = yielding_module.ElasticBound()
    bound.learn(one, 0.05, stronger)
    assert bound.below(one, 0.06) is None and bound.below(one, 0.05) is not None
    known = bound.below(one, 0.02)
    weaker = yielding_module.weaker_elastic_history(building, 0.02 * one.accel_g, one.dt_s, known, 0.02)
    run = yielding_module.stick_history(building, 0.02 * one.accel_g, one.dt_s)
    assert run.elastic and weaker.elastic
    assert weaker.floor_accel_g.tobytes() == run.floor_accel_g.tobytes()
    finite = np.isfinite(run.ductility)
    assert np.allclose(weaker.ductility[finite], run.ductility[finite], rtol=1e-9, atol=0.0)
    assert np.allclose(weaker.peak_drift_ratio, run.peak_drift_ratio, rtol=1e-9, atol=0.0)
    # a copy that yielded teaches nothing; a stronger copy than the one known is not known to stay elastic
    strong = yielding_module.stick_history(building, 3.0 * one.accel_g, one.dt_s)
    assert not strong.elastic
    bound.learn(one, 3.0, strong)
    assert bound.below(one, 1.0) is None
    with pytest.raises(ValueError, match="no stronger"):
        yielding_module.weaker_elastic_history(building, one.accel_g, one.dt_s, known, 0.1)
