"""The bookkeeping of a case test's checks: each comparison printed with
its error and tolerance, the failures counted, the exit status from their
count.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import sys


class Checks:
    """checks = Checks(); checks.near(...); checks.failures += 1 for a
    failure of one's own (printed by the caller); checks.exit() at the end"""

    def __init__(self, width=56):
        self.failures = 0
        self.width = width

    def near(self, label, value, expected, tol, scale=None):
        """|value - expected| / |scale| < tol, scale expected by default"""
        err = abs(value - expected) / abs(scale if scale else expected)
        ok = err < tol
        self.failures += not ok
        print("%-*s %13.7g expected %13.7g  error %.2e (tol %.1e) %s"
              % (self.width, label, value, expected, err, tol, "ok" if ok else "FAILED"))
        return ok

    def exit(self):
        print("%d check(s) failed" % self.failures)
        sys.exit(1 if self.failures else 0)
