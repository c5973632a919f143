"""Reference values of Optuna 3.6.1's TPE sampler for handsim's Java TPE (TpeReferenceTest).

For recorded histories (random parameters, objective values from fixed toy functions), this
writes what Optuna 3.6.1 computes deterministically: gamma and default weights, the split into
below/above trials (single objective and MOTPE's non-domination rank + hypervolume subset
selection), MOTPE's hypervolume-contribution weights, each parameter's Parzen estimators
(weights, means, sigmas, bounds), their log densities at candidate points, and the candidate
Optuna picks among those points. Also truncated-normal log densities in the tails and
hypervolumes.

One change to Optuna's behaviour: the Parzen estimator sorts its kernel means with numpy's
default argsort, which is not stable (numpy 2's SIMD sort orders equal means differently from
one CPU to the next), so for integer parameters with repeated values Optuna's bandwidths depend
on the machine. handsim breaks such ties by trial order with the prior last; this script makes
the estimator's argsort stable so the reference follows that same order, and marks every
estimator whose means have ties ("ties": true). Float parameters never tie here.

Regenerate (from the repository root, in a fresh virtual environment):
    python3 -m venv /tmp/optuna-venv
    /tmp/optuna-venv/bin/pip install optuna==3.6.1
    /tmp/optuna-venv/bin/python src/test/resources/tpe/optuna_reference.py \
        > src/test/resources/tpe/optuna-reference.json
"""

import json
import sys

import numpy as np
import optuna
from optuna._hypervolume import WFG
from optuna.distributions import FloatDistribution, IntDistribution
from optuna.samplers import TPESampler
from optuna.samplers._tpe import _truncnorm
from optuna.samplers._tpe import parzen_estimator
from optuna.samplers._tpe.sampler import (
    _calculate_weights_below_for_multi_objective,
    _split_trials,
    default_gamma,
    default_weights,
)
from optuna.trial import TrialState, create_trial

assert optuna.__version__ == "3.6.1", optuna.__version__
optuna.logging.set_verbosity(optuna.logging.ERROR)


class _StableArgsortNumpy:
    """numpy, with argsort stable (ties in input order); see the module's comment."""

    def __getattr__(self, name):
        return getattr(np, name)

    @staticmethod
    def argsort(a, *args, **kwargs):
        return np.argsort(a, kind="stable")


parzen_estimator.np = _StableArgsortNumpy()


def distribution(p):
    if p["int"]:
        return IntDistribution(p["low"], p["high"], log=p["log"])
    return FloatDistribution(p["low"], p["high"], log=p["log"])


def random_params(rng, space):
    """Uniform in each parameter's (log) range, rounded for integers."""
    out = {}
    for p in space:
        lo, hi = (np.log(p["low"]), np.log(p["high"])) if p["log"] else (p["low"], p["high"])
        x = rng.uniform(lo, hi)
        x = float(np.exp(x)) if p["log"] else float(x)
        out[p["name"]] = int(np.clip(round(x), p["low"], p["high"])) if p["int"] else x
    return out


def estimator_json(mpe):
    mix = mpe._mixture_distribution
    d = mix.distributions[0]
    return {
        "ties": has_ties(d.mu),
        "weights": mix.weights.tolist(),
        "mus": np.asarray(d.mu).tolist(),
        "sigmas": np.asarray(d.sigma).tolist(),
        "low": float(d.low),
        "high": float(d.high),
        "step": float(getattr(d, "step", 0.0)),
    }


def has_ties(mus):
    return len(np.unique(mus)) < len(mus)


def case(name, space, directions, objective, n_trials, seed, settings=None, ties=False):
    settings = settings or {}
    rng = np.random.RandomState(seed)
    study = optuna.create_study(directions=directions)
    dists = {p["name"]: distribution(p) for p in space}
    history = []
    for number in range(n_trials):
        params = random_params(rng, space)
        values = [float(v) for v in objective(params)]
        if ties:  # coarse values so that the single-objective sort meets ties
            values = [float(np.round(v, 0)) for v in values]
        study.add_trial(create_trial(params=params, distributions=dists, values=values))
        history.append({"number": number, "params": [params[p["name"]] for p in space], "values": values})

    sampler = TPESampler(
        consider_endpoints=settings.get("considerEndpoints", False),
        prior_weight=settings.get("priorWeight", 1.0),
    )
    trials = study.get_trials(deepcopy=False, states=(TrialState.COMPLETE, TrialState.PRUNED))
    n = len(trials)
    below, above = _split_trials(study, trials, sampler._gamma(n), False)
    out = {
        "name": name,
        "directions": directions,
        "settings": settings,
        "space": space,
        "history": history,
        "nBelow": sampler._gamma(n),
        "below": [t.number for t in below],
        "above": [t.number for t in above],
        "params": {},
    }
    if len(directions) > 1:
        out["belowHypervolumeWeights"] = _calculate_weights_below_for_multi_objective(
            study, below, None).tolist()

    for p in space:
        ss = {p["name"]: dists[p["name"]]}
        mpe_below = sampler._build_parzen_estimator(study, ss, below, handle_below=True)
        mpe_above = sampler._build_parzen_estimator(study, ss, above, handle_below=False)
        # candidates: 24 draws from l(x) (as Optuna draws them) and the range's ends
        drawn = mpe_below.sample(np.random.RandomState(seed + 1), 24)[p["name"]]
        candidates = np.concatenate([drawn, [p["low"], p["high"]]])
        samples = {p["name"]: candidates}
        log_below = mpe_below.log_pdf(samples)
        log_above = mpe_above.log_pdf(samples)
        chosen = TPESampler._compare(samples, sampler._compute_acquisition_func(samples, mpe_below, mpe_above))
        out["params"][p["name"]] = {
            "below": estimator_json(mpe_below),
            "above": estimator_json(mpe_above),
            "candidates": candidates.tolist(),
            "logPdfBelow": log_below.tolist(),
            "logPdfAbove": log_above.tolist(),
            "chosen": float(chosen[p["name"]]),
        }
    return out


def F(name, low, high, log=False):
    return {"name": name, "low": low, "high": high, "log": log, "int": False}


def I(name, low, high, log=False):
    return {"name": name, "low": low, "high": high, "log": log, "int": True}


def quadratic(p):
    return [(p["x"] - 1.3) ** 2 + 0.1 * (np.log10(p["lr"]) + 3) ** 2 + 0.05 * (p["k"] - 3) ** 2 + 0.01 * p["m"]]


def zdt1(p):
    g = 1 + 9 * p["b"]
    return [p["a"], g * (1 - np.sqrt(p["a"] / g))]


def three(p):
    return [p["a"] ** 2 + p["b"], (p["a"] - 1) ** 2 + p["b"] ** 2, (p["a"] - 0.5) ** 2 + (p["b"] - 1) ** 2]


MIXED = [F("x", -5.0, 5.0), F("lr", 1e-5, 1e-1, log=True), I("k", 0, 10), I("m", 1, 64, log=True)]
PLANAR = [F("a", 0.0, 1.0), F("b", 0.0, 1.0)]

cases = [
    case("single objective, 11 trials", MIXED, ["minimize"], quadratic, 11, 1),
    case("single objective, 30 trials (above weights ramp)", MIXED, ["minimize"], quadratic, 30, 2),
    case("single objective, 80 trials", MIXED, ["minimize"], quadratic, 80, 3),
    case("single objective, 300 trials (gamma capped at 25)", [F("x", -5.0, 5.0)], ["minimize"], quadratic_x := (lambda p: [(p["x"] - 1.3) ** 2]), 300, 4),
    case("maximize, tied values", MIXED, ["maximize"], quadratic, 40, 5, ties=True),
    case("consider endpoints, prior weight 2", MIXED, ["minimize"], quadratic, 35, 6,
         settings={"considerEndpoints": True, "priorWeight": 2.0}),
    case("two objectives (ZDT1), 40 trials", PLANAR, ["minimize", "minimize"], zdt1, 40, 7),
    case("two objectives, one maximized, 60 trials", PLANAR, ["minimize", "maximize"], zdt1, 60, 8),
    case("three objectives, 50 trials", PLANAR, ["minimize", "minimize", "minimize"], three, 50, 9),
]

# gamma and default weights
counts = [0, 1, 9, 10, 11, 24, 25, 26, 27, 40, 100, 249, 250, 251, 400]
weights = {"n": counts, "gamma": [default_gamma(n) for n in counts],
           "weights": [default_weights(n).tolist() for n in counts]}

# truncated-normal log densities, in the tails too
rng = np.random.RandomState(11)
truncnorm = []
for a, b in [(-1.0, 1.0), (-40.0, -30.0), (-25.0, -19.0), (30.0, 40.0), (5.0, 7.0), (-3.0, 0.0),
             (0.0, 2.0), (-0.5, 8.0), (-8.0, 0.1), (2.0, 2.5), (-1e-3, 1e-3)]:
    xs = np.concatenate([[a, b], rng.uniform(a, b, 5)])
    truncnorm.append({"a": a, "b": b, "x": xs.tolist(),
                      "logPdf": _truncnorm.logpdf(xs, a, b).tolist(),
                      "logMass": float(_truncnorm._log_gauss_mass(np.asarray([a]), np.asarray([b]))[0])})

# hypervolumes
hypervolumes = []
for dim, n in [(2, 1), (2, 7), (3, 2), (3, 9), (4, 8)]:
    pts = rng.uniform(0, 1, (n, dim))
    ref = np.full(dim, 1.1)
    hypervolumes.append({"points": pts.tolist(), "reference": ref.tolist(),
                         "hypervolume": float(WFG().compute(pts, ref))})

json.dump({"optuna": optuna.__version__, "numpy": np.__version__, "weights": weights,
           "truncnorm": truncnorm, "hypervolumes": hypervolumes, "cases": cases},
          sys.stdout, indent=1)
print()
