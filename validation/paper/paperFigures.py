"""What the paper-figure scripts share: where things go, the particle
table's derived series, and the claims file each script adds its numbers to
(the cases, their tables and the riser come from the riserfoam package).

SPDX-License-Identifier: GPL-3.0-or-later
"""
import json
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import numpy as np  # noqa: E402
from riserfoam.carrier import D, UCM, Riser  # noqa: E402,F401  (for the figure scripts)
from riserfoam.cases import RiserCase  # noqa: E402,F401

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "../.."))
__all__ = ["D", "UCM", "Riser", "RiserCase", "np", "plt", "root", "scratch", "figures", "results",
           "quick", "claim", "dominant_frequency", "phase_lag", "save"]

# RISER_VALIDATION_OUT (the quick test's scratch folder) redirects the
# figures, the claims and the cases away from the tree
out = os.environ.get("RISER_VALIDATION_OUT")
scratch = os.path.join(out or os.path.join(root, "build/validation"), "paper")
figures = os.path.join(out, "figures") if out else os.path.join(root, "validation/figures")
results = os.path.join(out, "results") if out else os.path.join(here, "results")
os.makedirs(figures, exist_ok=True)
quick = os.environ.get("RISER_VALIDATION_QUICK") == "1"
os.makedirs(scratch, exist_ok=True)
os.makedirs(results, exist_ok=True)


def claim(key, value, text):
    """record one of our numbers for the claims table (results/claims.json)"""
    name = os.path.join(results, "claims.json")
    data = json.load(open(name)) if os.path.exists(name) else {}
    data[key] = {"value": value, "text": text}
    json.dump(data, open(name, "w"), indent=1, sort_keys=True)
    print("%s: %s" % (key, text))


def dominant_frequency(t, y):
    """the strongest nonzero frequency of y(t) (uniform t), by FFT"""
    y = np.asarray(y) - np.mean(y)
    spectrum = np.abs(np.fft.rfft(y * np.hanning(len(y))))
    freqs = np.fft.rfftfreq(len(y), t[1] - t[0])
    return freqs[1 + np.argmax(spectrum[1:])]


def phase_lag(t, y, reference, f):
    """phase of y's component at f minus the reference's [degrees]"""
    w = 2 * np.pi * f
    a = np.sum((np.asarray(y) - np.mean(y)) * np.exp(-1j * w * t))
    b = np.sum((np.asarray(reference) - np.mean(reference)) * np.exp(-1j * w * t))
    return float(np.degrees(np.angle(a / b)))


def save(fig, name):
    fig.tight_layout()
    fig.savefig(os.path.join(figures, name), dpi=100)
    plt.close(fig)
    print("wrote", os.path.join(figures, name))
