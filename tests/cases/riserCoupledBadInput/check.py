"""riserCoupledFoam's refusals: each bad input stops the run with an error
naming the entry (and its allowed range), before the first step (among
them a cloud without the coarse-particle kernel's sub-dictionary, which
riserCoupledFoam requires, and a kernel out of its range; a turbulence
model whose field is missing from the start time, refused naming the
model's entry and the field's file, and a misspelt simulationType,
refused by OpenFOAM naming the entry and the allowed types; the explicit
source scheme for U; a drive's pulsation without its amplitude or its
frequency, or out of range; a drag with a voidage function in a one-way run;
cellValueSourceCorrection or a steady cloud with the kernel of type
diffusion); a
cloud that is not coupled runs one-way and says so."""
import os
import shutil
import subprocess

from riserfoam import cases, foamfields

failures = 0
base = os.path.abspath("base")
cases.coupled_pipe_case(base, 6, 2, dt=1.0, end=1.0)
open_riser = os.path.abspath("openBase")
cases.coupled_pipe_case(open_riser, 6, 2, dt=1.0, end=1.0)
os.remove(os.path.join(open_riser, "system", "blockMeshDict"))
cases.riser_mesh(open_riser, 0.1, 0.1, 6, nz=2, ends="wall")
for field, ends in (("U", "type noSlip;"), ("p", "type zeroGradient;")):
    for patch in ("bottom", "top"):
        foamfields.edit(os.path.join(open_riser, "0", field),
                        r"%s \{ type cyclic; \}" % patch, "%s { %s }" % (patch, ends))
turbulent = os.path.abspath("turbulentBase")
shutil.copytree(base, turbulent)
cases.coupled_pipe_RAS(turbulent, 0.01)
count = 0


def run(solver, edit, source=base):
    """a copy of source changed by edit(case); the solver's exit status and log"""
    global count
    count += 1
    case = os.path.abspath("case%d" % count)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(source, case)
    edit(case)
    with open(os.path.join(case, "log"), "w") as log:
        status = subprocess.run([solver, "-case", case], stdout=log,
                                stderr=subprocess.STDOUT).returncode
    return status, open(os.path.join(case, "log")).read()


def expect(label, text, edit, solver="riserCoupledFoam", source=base, io=False):
    """the run stops (non-zero exit) with a line holding text (and, if io,
    as a FatalIOError)"""
    global failures
    status, log = run(solver, edit, source)
    line = next((l.strip() for l in log.splitlines() if text in l), None)
    if status != 0 and line and (not io or "FOAM FATAL IO ERROR" in log):
        print("ok: %s stops with: %s" % (label, line[:140]))
    else:
        print("FAILED: %s (exit %d) did not stop with '%s'\n%s" % (label, status, text, log[-1500:]))
        failures += 1


def riser(entries):
    """replace riserProperties' drive and add entries"""
    def edit(case):
        path = os.path.join(case, "constant/riserProperties")
        text = open(path).read()
        open(path, "w").write(text.replace("drive {  }", entries))
    return edit


def cloud(old, new):
    def edit(case):
        foamfields.edit(os.path.join(case, "constant/kinematicCloudProperties"), old, new)
    return edit


expect("carrier exact", "entry 'carrier' = exact", riser("drive {  }\ncarrier exact;"))
expect("no drive in a periodic riser", "entry 'drive' missing", riser(""))
expect("a drive in an open riser", "entry 'drive': the riser section is not periodic",
       lambda case: None, source=open_riser)
expect("bulkVelocity < 0", "entry 'bulkVelocity' = -1 is outside the allowed range [0, 100]",
       riser("drive { bulkVelocity -1; }"))
expect("relaxation 0", "entry 'relaxation' = 0 is outside the allowed range (0, 1]",
       riser("drive { relaxation 0; }"))
expect("an unknown drive entry", "unknown entry 'bulk'", riser("drive { bulk 1; }"))
expect("pulseAmplitude without pulseFrequency",
       "entry 'pulseAmplitude' without 'pulseFrequency'", riser("drive { pulseAmplitude 0.1; }"))
expect("pulseFrequency without pulseAmplitude",
       "entry 'pulseFrequency' without 'pulseAmplitude'", riser("drive { pulseFrequency 1; }"))
expect("pulseFrequency 0", "entry 'pulseFrequency' = 0 is outside the allowed range (0, 1000]",
       riser("drive { pulseAmplitude 0.1; pulseFrequency 0; }"))
expect("pulseFrequency nan", "entry 'pulseFrequency' = nan is not a finite number",
       riser("drive { pulseAmplitude 0.1; pulseFrequency nan; }"))
expect("pulseAmplitude nan", "entry 'pulseAmplitude' = nan is not a finite number",
       riser("drive { pulseAmplitude nan; pulseFrequency 1; }"))
expect("pulseAmplitude < 0", "entry 'pulseAmplitude' = -0.1 is outside the allowed range [0, 100]",
       riser("drive { pulseAmplitude -0.1; pulseFrequency 1; }"))
expect("alphaMax 0.8", "entry 'alphaMax' = 0.8 is outside the allowed range (0, 0.74]",
       cloud(r"alphaMax 0.6;", "alphaMax 0.8;"))
expect("no alphaMax", "alphaMax", cloud(r"alphaMax 0.6;", ""))
expect("no kernel", "riserCoupledFoam needs the sub-dictionary 'kernel'",
       cloud(r"kernel \{ type none; \}", ""))
expect("U explicit (the reaction needs its semi-implicit split)",
       "entry 'sourceTerms { schemes { U ... } }' = explicit",
       lambda case: (cloud("coupled +false;", "coupled true;")(case),
                     cloud(r"U semiImplicit 1;", "U explicit 1;")(case)), io=True)
# a coefficient other than 1 relaxes the reaction toward the previous
# step's: the carrier would take a fraction of what the particles feel
for c in ("0.5", "0", "-1", "2", "1e300"):
    expect("U semiImplicit %s (the reaction relaxed)" % c,
           "entry 'sourceTerms { schemes { U semiImplicit %s; } }'" % ("1e+300" if c == "1e300" else c),
           lambda case, c=c: (cloud("coupled +false;", "coupled true;")(case),
                              cloud(r"U semiImplicit 1;", "U semiImplicit %s;" % c)(case)), io=True)
# the face flux's time correction and the particles' Du/Dt are Euler's
for scheme in ("backward", "CrankNicolson 0.9"):
    expect("ddt scheme %s (the carrier steps with Euler)" % scheme,
           "entry 'ddtSchemes { ddt(U) ... }' = %s" % scheme.split()[0],
           lambda case, scheme=scheme: foamfields.edit(
               os.path.join(case, "system/fvSchemes"), r"default +Euler;",
               "default %s;" % scheme), io=True)
expect("voidage in a one-way run (its carrier is not displaced)",
       "entry 'voidage' = wenYu: the cloud is not coupled (coupled false)",
       cloud(r"wallCorrectedDrag \{ law continuous; \}",
             "wallCorrectedDrag { law continuous; voidage wenYu; }"), io=True)
expect("a kernel wider than the riser", "entry 'width'",
       cloud(r"kernel \{ type none; \}",
             "kernel { type diffusion; width 0.2; widthUnit metres; }"))
expect("cellValueSourceCorrection with the kernel (it takes a cell's own deposit)",
       "entry 'cellValueSourceCorrection' = on",
       lambda case: (cloud("coupled +false;", "coupled true;")(case),
                     cloud("cellValueSourceCorrection off;", "cellValueSourceCorrection on;")(case),
                     cloud(r"kernel \{ type none; \}",
                           "kernel { type diffusion; width 0.08; widthUnit metres; }")(case)),
       io=True)
expect("a steady cloud with the kernel (its sources are relaxed without the points')",
       "entry 'transient' = no",
       lambda case: (cloud("coupled +false;", "coupled true;")(case),
                     cloud("transient +yes;", "transient no; calcFrequency 1; maxTrackTime 1;")(case),
                     cloud(r"sourceTerms \{", "sourceTerms { resetOnStartup false;")(case),
                     cloud(r"kernel \{ type none; \}",
                           "kernel { type diffusion; width 0.08; widthUnit metres; }")(case)),
       io=True)
expect("frame riser on a moving mesh (the check riserParcelFoam shares)",
       "frame riser needs a static mesh",
       lambda case: foamfields.write_dictionary(os.path.join(case, "constant/dynamicMeshDict"),
                                                "dynamicFvMesh dynamicMotionSolverFvMesh;\n"
                                                "motionSolverLibs (fvMotionSolvers);\n"
                                                "motionSolver solidBody;\n"
                                                "solidBodyMotionFunction riserOscillation;\n"))
expect("riserParcelFoam with a drive", "entry 'drive': riserParcelFoam imposes the analytic carrier",
       lambda case: None, solver="riserParcelFoam")
expect("riserParticle with a drive", "entry 'drive': riserParticle imposes the analytic carrier",
       lambda case: None, solver="riserParticle")
for field in ("k", "omega", "nut"):
    expect("kOmegaSST without 0/%s" % field,
           "entry 'RASModel' = kOmegaSST (simulationType RAS): the model cannot be built from the"
           " start time 0: cannot find file \"%s\"" % os.path.join(os.path.abspath("case%d" % (count + 1)),
                                                            "0", field),
           lambda case: os.remove(os.path.join(case, "0", field)), source=turbulent, io=True)
expect("simulationType misspelt", "Unknown simulationType type RANS",
       lambda case: foamfields.edit(os.path.join(case, "constant/turbulenceProperties"),
                                    r"simulationType RAS;", "simulationType RANS;"),
       source=turbulent, io=True)

status, log = run("riserCoupledFoam", lambda case: None)
if status == 0 and "The cloud is not coupled (coupled false)" in log:
    print("ok: a cloud with coupled false runs one-way and says so")
else:
    print("FAILED: coupled false (exit %d) did not run one-way with its note" % status)
    failures += 1
print("%d check(s) failed" % failures)
raise SystemExit(1 if failures else 0)
