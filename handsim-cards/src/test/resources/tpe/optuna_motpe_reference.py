"""Reference values of Optuna 3.6.1's MOTPE for recorded three-objective histories (MotpeReferenceTest).

For histories of three minimised objectives, shaped as Double Lift's (|h1 - h_target|, |h2 - h_target|,
|d3|: non-negative, with ties at zero and whole fronts of equal values), this writes what Optuna 3.6.1
computes deterministically: the below/above split (non-domination ranks, then greedy hypervolume subset
selection of the last rank), MOTPE's hypervolume-contribution weights of the below trials, the
hypervolume of the below trials against Optuna's reference point, and each parameter's Parzen
estimators for independent (multivariate=False) and multivariate (multivariate=True) TPE: weights,
means, bandwidths, and the log densities of 24 candidate points (drawn from the below estimator)
under l(x) and g(x), with the candidate Optuna picks.

The estimator's argsort is made stable, as optuna_reference.py beside this file explains.

Regenerate (from the repository root, in the virtual environment of optuna_reference.py):
    /tmp/optuna-venv/bin/python handsim-cards/src/test/resources/tpe/optuna_motpe_reference.py \
        > handsim-cards/src/test/resources/tpe/optuna-motpe-reference.json
"""

import json
import sys

import numpy as np
import optuna
from optuna._hypervolume import WFG
from optuna.distributions import FloatDistribution
from optuna.samplers import TPESampler
from optuna.samplers._tpe import parzen_estimator
from optuna.samplers._tpe.sampler import _calculate_weights_below_for_multi_objective, _split_trials
from optuna.study._multi_objective import _get_pareto_front_trials_by_trials
from optuna.trial import TrialState, create_trial

assert optuna.__version__ == "3.6.1", optuna.__version__
optuna.logging.set_verbosity(optuna.logging.ERROR)


class _StableArgsortNumpy:
    def __getattr__(self, name):
        return getattr(np, name)

    @staticmethod
    def argsort(a, *args, **kwargs):
        return np.argsort(a, kind="stable")


parzen_estimator.np = _StableArgsortNumpy()

# Double Lift's search space (configs/cards/double-lift-study.json's shape)
SPACE = [("hStart", -5e-4, 1e-3), ("t0", 0.0, 0.05), ("t1", 0.1, 0.15), ("vp", 0.002, 0.008),
         ("t2", 0.15, 0.25), ("t3", 0.35, 0.45), ("vs", 0.01, 0.05)]


def lift_like(p, rng, round_to):
    """Three non-negative objectives of a pinch and lift (m), rounded so that ties occur."""
    lift = p["vs"] * (p["t3"] - p["t2"])
    grip = p["vp"] * (p["t1"] - p["t0"]) - 2e-4 - max(p["hStart"], 0) * 0.2
    h1 = lift * min(1.0, max(0.0, grip / 2e-4)) * (0.8 + 0.2 * rng.rand())
    h2 = h1 * min(1.0, max(0.0, (grip - 5e-5) / 1.5e-4))
    d3 = max(0.0, grip - 2.5e-4) * 10 * rng.rand()
    v = [abs(h1 - 0.005), abs(h2 - 0.005), d3]
    return [float(np.round(x / round_to) * round_to) for x in v]


def case(name, n_trials, seed, round_to, multivariate):
    rng = np.random.RandomState(seed)
    study = optuna.create_study(directions=["minimize"] * 3)
    dists = {k: FloatDistribution(lo, hi) for k, lo, hi in SPACE}
    history = []
    for number in range(n_trials):
        params = {k: float(rng.uniform(lo, hi)) for k, lo, hi in SPACE}
        values = lift_like(params, rng, round_to)
        study.add_trial(create_trial(params=params, distributions=dists, values=values))
        history.append({"number": number, "params": [params[k] for k, _, _ in SPACE], "values": values})
    sampler = TPESampler(multivariate=multivariate)
    trials = study.get_trials(deepcopy=False, states=(TrialState.COMPLETE,))
    n = len(trials)
    below, above = _split_trials(study, trials, sampler._gamma(n), False)
    weights = _calculate_weights_below_for_multi_objective(study, below, None)
    losses = np.array([t.values for t in below])
    worst = np.max(losses, axis=0)
    reference = np.maximum(1.1 * worst, 0.9 * worst)
    reference[reference == 0] = 1e-12
    out = {
        "name": name,
        "multivariate": multivariate,
        "space": [{"name": k, "low": lo, "high": hi, "log": False, "int": False} for k, lo, hi in SPACE],
        "history": history,
        "nBelow": sampler._gamma(n),
        "below": [t.number for t in below],
        "above": [t.number for t in above],
        "paretoFront": sorted(t.number for t in _get_pareto_front_trials_by_trials(trials, study.directions)),
        "belowHypervolumeWeights": weights.tolist(),
        "belowReference": reference.tolist(),
        "belowHypervolume": float(WFG().compute(losses, reference)),
    }
    space = {k: dists[k] for k, _, _ in SPACE}
    mpe_below = sampler._build_parzen_estimator(study, space, below, handle_below=True)
    mpe_above = sampler._build_parzen_estimator(study, space, above, handle_below=False)
    samples = mpe_below.sample(np.random.RandomState(seed + 1), 24)
    log_below = mpe_below.log_pdf(samples)
    log_above = mpe_above.log_pdf(samples)
    chosen = TPESampler._compare(samples, log_below - log_above)

    def estimator(mpe):
        mix = mpe._mixture_distribution
        return {"weights": mix.weights.tolist(),
                "mus": [np.asarray(d.mu).tolist() for d in mix.distributions],
                "sigmas": [np.asarray(d.sigma).tolist() for d in mix.distributions]}

    out["estimators"] = {"below": estimator(mpe_below), "above": estimator(mpe_above)}
    out["candidates"] = [[float(samples[k][i]) for k, _, _ in SPACE] for i in range(24)]
    out["logPdfBelow"] = log_below.tolist()
    out["logPdfAbove"] = log_above.tolist()
    out["chosen"] = [float(chosen[k]) for k, _, _ in SPACE]
    return out


cases = [
    case("15 trials, independent", 15, 21, 1e-5, False),
    case("40 trials, ties at 0.1 mm, independent", 40, 22, 1e-4, False),
    case("40 trials, ties at 0.1 mm, multivariate", 40, 22, 1e-4, True),
    case("120 trials, multivariate", 120, 23, 1e-6, True),
    case("300 trials (gamma capped at 25), independent", 300, 24, 1e-6, False),
]
json.dump({"optuna": optuna.__version__, "numpy": np.__version__, "cases": cases}, sys.stdout, indent=1)
print()
