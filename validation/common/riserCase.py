"""Riser cases for the validation scripts: a copy of a tutorial with its
riser, run length and releases changed, run by the mesh-free engine
(riserParticle) or the solver (riserParcelFoam), and its particle table read
back (the columns of riserParticleTable, the same for both engines).

SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import re
import shutil
import subprocess
import sys

import numpy as np

D, UCM = 0.1, 1.0           # the paper's scenes: D = 0.1 m, u_cm = 1 m/s
HEADER = "FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n"
COLUMNS = ("t origProc origId x y z Ux Uy Uz xr yr Urx Ury Urz lift Fc_x Fc_y Fc_z "
           "deltaN deltaT").split()


def carrier_speed(r):
    """The Poiseuille speed at distance r from the axis"""
    return UCM * (1.0 - (2.0 * r / D) ** 2)


class RiserCase:
    def __init__(self, root, scratch, name, tutorial="oscillatingNoContact"):
        self.root = root
        self.path = os.path.join(scratch, name)
        shutil.rmtree(self.path, ignore_errors=True)
        os.makedirs(self.path)
        source = os.path.join(root, "tutorials/riser", tutorial)
        for sub in ("0", "constant", "system"):
            shutil.copytree(os.path.join(source, sub), os.path.join(self.path, sub),
                            ignore=shutil.ignore_patterns("polyMesh"))
        self.forces = None

    def _edit(self, relative, pattern, replacement):
        name = os.path.join(self.path, relative)
        text, n = re.subn(pattern, replacement, open(name).read(), flags=re.M)
        if n == 0:
            sys.exit("riserCase: no '%s' in %s" % (pattern, name))
        open(name, "w").write(text)

    def riser(self, A=None, f=None, phi0=None):
        """amplitude [D], frequency [u_cm/D], phase (the paper's units)"""
        props = "constant/riserProperties"
        if A is not None:
            self._edit(props, r"^A\s.*;", "A           [0 1 0 0 0 0 0] %r;" % (A * D))
        if f is not None:
            self._edit(props, r"^f\s.*;", "f           [0 0 -1 0 0 0 0] %r;" % (f * UCM / D))
        if phi0 is not None:
            self._edit(props, r"^phi0\s.*;", "phi0        %r;" % phi0)
        return self

    def run_for(self, endTime, deltaT=None):
        """endTime and deltaT [s] (deltaT: the table's row interval)"""
        self._edit("system/controlDict", r"^endTime\s.*;", "endTime         %r;" % endTime)
        self._edit("system/controlDict", r"^writeInterval\s.*;",
                   "writeInterval   %r;" % endTime)
        if deltaT is not None:
            self._edit("system/controlDict", r"^deltaT\s.*;", "deltaT          %r;" % deltaT)
        return self

    def releases(self, points, d=0.01):
        """one particle per (x, y) [D] at z = 0.5 D, released with the local
        carrier speed relative to the riser (the tutorials' riser frame)"""
        blocks = []
        for i, (x, y) in enumerate(points):
            r = np.hypot(x, y) * D
            open(os.path.join(self.path, "constant/kinematicCloudPositions%d" % i), "w").write(
                HEADER.replace("class dictionary", "class vectorField")
                % ("kinematicCloudPositions%d" % i)
                + "((%r %r %r))\n" % (x * D, y * D, 0.5 * D))
            blocks.append(
                "        release%d\n        {\n"
                "            type manualInjection; massTotal 0; parcelBasisType fixed;\n"
                "            nParticle 1; SOI 0; positionsFile \"kinematicCloudPositions%d\";\n"
                "            U0 (0 0 %r);\n"
                "            sizeDistribution { type fixedValue; fixedValueDistribution { value %r; } }\n"
                "        }\n" % (i, i, carrier_speed(r), d))
        name = os.path.join(self.path, "constant/kinematicCloudProperties")
        text = open(name).read()
        start = text.index("    injectionModels")
        depth, end = 0, text.index("{", start)
        for k in range(end, len(text)):
            depth += {"{": 1, "}": -1}.get(text[k], 0)
            if depth == 0:
                end = k + 1
                break
        text = text[:start] + "    injectionModels\n    {\n" + "".join(blocks) + "    }" + text[end:]
        open(name, "w").write(text)
        return self

    def without_force(self, name):
        """drop a particle force (a line 'name;' or a block 'name { ... }')"""
        props = "constant/kinematicCloudProperties"
        text = open(os.path.join(self.path, props)).read()
        if re.search(r"^\s*%s\s*\{" % name, text, flags=re.M):
            self._edit(props, r"^\s*%s\s*\{[^}]*\}\n" % name, "")
        else:
            self._edit(props, r"^\s*%s;.*\n" % name, "")
        return self

    def with_basset(self, windowTime=0.01):
        props = "constant/kinematicCloudProperties"
        text = open(os.path.join(self.path, props)).read()
        if "riserBasset" not in text:
            self._edit(props, r"^(\s*)riserFluidStress;",
                       r"\1riserBasset { coefficient michaelidesRoig; method windowTail; "
                       r"windowTime %r; }\n\1riserFluidStress;" % windowTime)
        return self

    def engine_settings(self, text):
        """system/riserParticleDict's entries (integrator, writeFrom, ...)"""
        open(os.path.join(self.path, "system/riserParticleDict"), "w").write(
            HEADER % "riserParticleDict" + text + "\n")
        return self

    def _run(self, command, log, may_fail=False):
        """the command's log; None if it failed and may_fail"""
        with open(os.path.join(self.path, log), "w") as out:
            done = subprocess.run(command, cwd=self.path, stdout=out, stderr=subprocess.STDOUT)
        text = open(os.path.join(self.path, log)).read()
        if done.returncode != 0:
            if may_fail:
                return None
            sys.exit("riserCase: %s failed in %s (see %s)" % (command[0], self.path, log))
        return text

    def engine(self, *args):
        """run riserParticle; returns self"""
        self._run(["riserParticle", "-case", self.path] + list(args), "log.riserParticle")
        return self

    def engine_log(self, *args, may_fail=False):
        """run riserParticle; its log, or None if a particle's integration
        failed (a step too large) and may_fail"""
        log = self._run(["riserParticle", "-case", self.path] + list(args), "log.riserParticle",
                        may_fail=True)
        if log is None:
            text = open(os.path.join(self.path, "log.riserParticle")).read()
            if not (may_fail and "failed: " in text):
                sys.exit("riserCase: riserParticle failed in %s:\n%s" % (self.path, text[-2000:]))
        return log

    def solver(self, cells=12, length=2.0):
        """mesh (O-grid, cyclic ends, length [D]) and run riserParcelFoam"""
        self._run([os.path.join(self.root, "bin/riserMesh"), "-D", str(D), "-L", str(length * D),
                   "-n", str(cells), "-ends", "cyclic", "-case", self.path], "log.riserMesh")
        self._run(["blockMesh", "-case", self.path], "log.blockMesh")
        self._run(["riserParcelFoam", "-case", self.path], "log.riserParcelFoam")
        return self

    def table(self, engine="riserParticle"):
        """{origId: dict of columns (numpy arrays)}, the engine's or the solver's"""
        name = ("postProcessing/riserParticle/particles.dat" if engine == "riserParticle" else
                "postProcessing/lagrangian/kinematicCloud/riserParticleTable/particles.dat")
        lines = open(os.path.join(self.path, name)).read().splitlines()
        names = [l[2:].split() for l in lines if l.startswith("# t ")][0]
        data = np.array([[float(v) for v in l.split()] for l in lines if l and l[0] != "#"])
        out = {}
        for pid in sorted(set(data[:, 2].astype(int))):
            rows = data[data[:, 2] == pid]
            out[pid] = {n: rows[:, k] for k, n in enumerate(names)}
        return out

    def contacts(self):
        """the engine's contacts: rows of origId start end side maxOverlap impact rebound"""
        name = os.path.join(self.path, "postProcessing/riserParticle/contacts.dat")
        rows = [l.split() for l in open(name) if l.strip() and l[0] != "#"]
        return np.array(rows, dtype=float).reshape(-1, 7)

    def budget(self):
        """riserParticle -budget's rows: {force: (rms/W, max/W, lift change/D,
        trajectory change/D, cpu ratio)} (None where not dropped)"""
        self.engine("-budget")
        out = {}
        for l in open(os.path.join(self.path, "postProcessing/riserParticle/budget.dat")):
            if l[0] == "#":
                continue
            c = l.split()
            out[c[0]] = tuple(float(v) if v not in ("-", "failed") else None for v in c[1:])
        return out
