"""The steady part of a time series and the standard error of its mean,
for the transport statistics of a riser cloud (bin/riserStatistics).

A run's statistics (C_v, slip, lifting efficiency, contact rates) drift
while the ores settle into the flow, so that a mean over the whole run
depends on where it starts. Two classical tools of simulation output
analysis are used:

- the start of the steady window by MSER-5, the marginal standard error
  rule on batches of 5 samples (White, Simulation 69, 323, 1997; Franklin
  & White, Proc. Winter Simulation Conference 2008): of the batch means
  Y_1..Y_m, drop the first d that minimise
      MSER(d) = sum_{i>d} (Y_i - mean(Y_{d+1..m}))^2 / (m - d)^2,
  searching d in [0, m/2] (a minimum at m/2, the end of the search, means
  the series may not have settled by the middle of the run: reported as
  not settled);
- the standard error of the window's mean by non-overlapping batch means
  (Schmeiser, Oper. Res. 30, 556, 1982: 10 to 30 batches): the window cut
  into b = 10 batches of equal length, SE = sd(batch means)/sqrt(b), which
  holds for correlated samples as long as a batch is longer than the
  correlation time (the lag-1 correlation of the batch means is reported
  as the check);
- a trend test on the window: the least-squares slope of the 10 batch
  means against time, over its standard error; |t| above 3 (1.7 % of
  stationary windows by Student's t with 8 degrees of freedom) marks the
  window as not settled, as does an MSER-5 truncation at the end of its
  search;
- two runs compared (dry against wet, one carrier against another): the
  difference of their steady means over its standard error,
      z = (mean_b - mean_a) / sqrt(se_a^2 + se_b^2),
  the runs independent; |z| above 3 marks a difference the runs resolve
  (about 1 % of pairs of runs of one scene by Student's t with the 18
  degrees of freedom of two sets of 10 batches: 0.8 %).

License: GPL-3.0-or-later
"""
import math

import numpy as np

BATCH = 5          # MSER-5's batch of samples
BATCHES = 10       # batches of the standard error


def mser5_start(x):
    """(index of the first sample of the steady window, settled): the
    MSER-5 truncation of the series x, searched over the first half;
    settled is False when the best truncation is the half itself (the
    drift may go on beyond it)"""
    x = np.asarray(x, dtype=float)
    m = len(x) // BATCH
    if m < 4:
        raise ValueError("%d samples: MSER-5 needs at least %d" % (len(x), 4 * BATCH))
    y = x[:m * BATCH].reshape(m, BATCH).mean(axis=1)
    best, where = math.inf, 0
    for d in range(m // 2 + 1):
        tail = y[d:]
        value = np.sum((tail - tail.mean()) ** 2) / (m - d) ** 2
        if value < best:
            best, where = value, d
    return where * BATCH, where < m // 2


def batch_means(x, batches=BATCHES):
    """(mean, standard error, lag-1 correlation of the batch means, t of
    their trend) of the series x by non-overlapping batch means"""
    x = np.asarray(x, dtype=float)
    size = len(x) // batches
    if size < 1:
        raise ValueError("%d samples: %d batches need at least as many" % (len(x), batches))
    y = x[len(x) - size * batches:].reshape(batches, size).mean(axis=1)
    se = float(np.std(y, ddof=1) / math.sqrt(batches))
    centred = y - y.mean()
    denominator = float(np.sum(centred ** 2))
    lag1 = float(np.sum(centred[1:] * centred[:-1]) / denominator) if denominator > 0 else 0.0
    k = np.arange(batches) - 0.5 * (batches - 1)
    slope = float(np.sum(k * centred) / np.sum(k * k))
    residual = centred - slope * k
    slopeSe = math.sqrt(float(np.sum(residual ** 2)) / (batches - 2) / float(np.sum(k * k)))
    trend = slope / slopeSe if slopeSe > 0 else (0.0 if slope == 0 else math.inf)
    return float(np.mean(x)), se, lag1, trend


def steady_mean(t, x, start_time=None):
    """the steady window of the series x(t) (from start_time if given, else
    by MSER-5) and its mean: a dict with start (time), samples, mean, se,
    lag1, trend and settled"""
    t, x = np.asarray(t, dtype=float), np.asarray(x, dtype=float)
    if start_time is None:
        first, settled = mser5_start(x)
    else:
        first, settled = int(np.searchsorted(t, start_time - 1e-12 * max(1.0, abs(start_time)))), True
    window = x[first:]
    mean, se, lag1, trend = batch_means(window)
    return dict(start=float(t[first]) if first < len(t) else math.nan, samples=len(window),
                mean=mean, se=se, lag1=lag1, trend=trend, settled=settled and abs(trend) <= 3)


def compare(a, b):
    """The difference of two runs' steady means (dicts of steady_mean):
    (b - a, its standard error, z = difference / standard error)"""
    difference = b["mean"] - a["mean"]
    se = math.hypot(a["se"], b["se"])
    return difference, se, difference / se if se > 0 else math.nan
