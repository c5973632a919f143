"""Optuna 3.6.1's own TPESampler on the problems of TpeSamplerTest, for comparison with handsim's
(the figures quoted there and in docs/cards.md). Same budgets and seeds 1-20 (1-5 for ZDT1),
Optuna's numpy generator instead of Java's, so the numbers are comparable in distribution only.

    /tmp/optuna-venv/bin/python src/test/resources/tpe/optuna_benchmark.py
(the virtual environment of optuna_reference.py)
"""

import math

import numpy as np
import optuna
from optuna._hypervolume import WFG

assert optuna.__version__ == "3.6.1", optuna.__version__
optuna.logging.set_verbosity(optuna.logging.ERROR)


def quadratic(t):
    return (t.suggest_float("x", -10, 10) - 2) ** 2


def branin(t):
    x, y = t.suggest_float("x", -5, 10), t.suggest_float("y", 0, 15)
    b, c, s = 5.1 / (4 * math.pi**2), 5 / math.pi, 1 / (8 * math.pi)
    return (y - b * x * x + c * x - 6) ** 2 + 10 * (1 - s) * math.cos(x) + 10 - 0.397887


def zdt1(t):
    a, b = t.suggest_float("a", 0, 1), t.suggest_float("b", 0, 1)
    g = 1 + 9 * b
    return a, g * (1 - math.sqrt(a / g))


for name, f in (("quadratic", quadratic), ("Branin", branin)):
    best = []
    for seed in range(1, 21):
        study = optuna.create_study(sampler=optuna.samplers.TPESampler(seed=seed))
        study.optimize(f, n_trials=50)
        best.append(study.best_value)
    print(f"{name}, 50 trials, seeds 1-20: median best {np.median(best):.3g}")

for seed in range(1, 6):
    study = optuna.create_study(directions=["minimize", "minimize"], sampler=optuna.samplers.TPESampler(seed=seed))
    study.optimize(zdt1, n_trials=100)
    inside = np.array([t.values for t in study.trials if t.values[0] <= 1 and t.values[1] <= 1])
    hv = WFG().compute(inside, np.array([1.0, 1.0])) if len(inside) else 0.0
    print(f"ZDT1, 100 trials, seed {seed}: hypervolume {hv:.4f}")
