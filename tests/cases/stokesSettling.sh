# Shared by the case tests of the riser forces under the stock solvers
# (sourced, not run): a sphere released from rest in a quiescent fluid,
# settling at a terminal Re_p below 1, where the paper's drag law is the
# wall-corrected Stokes drag F = -3 pi mu d K U_p, linear in the velocity.
# With the buoyant weight W = (rho_p - rho_f) V g (stock force gravity) and
# the added mass C_A rho_f V (riserAddedMass) the settling speed is then
#     v(t) = v_t (1 - exp(-t/tau)),   tau = (rho_p + C_A rho_f) v_t / ((rho_p - rho_f) g),
# with v_t from the weight-drag balance of the oracle terminalVelocity.cpp.
# The age of the sphere at time t is t + deltaT: OpenFOAM v1912 moves a
# parcel injected at the start of a step through that step twice, once
# when injecting it (InjectionModel::inject) and again with the cloud
# (Cloud::move sets every parcel's step fraction back to 0).
# The drag's lagrangian field F_wallCorrectedDrag (particleForceFields) must
# be W v(t)/v_t, and the forces that vanish in a fluid at rest (fluid stress,
# lift, the explicit part of the added mass) must be negligible against W.
# Without wallCorrectedDrag the sphere falls freely; without riserAddedMass
# its speed at t = tau is higher by 6% of v_t: both fail the check.
#
# stokes_settling_check <case folder> <folder holding terminalVelocity>
#     <rho_f> <mu> <tolerance> <carrier field name> <solver log>
# The particle's and the forces' inputs are read from the case.

stokes_settling_check()
{
    local case="$1" tools="$2" rhoF="$3" mu="$4" tol="$5" Uname="$6" log="$7"
    local cloud=constant/kinematicCloudProperties
    local forces=subModels/particleForces
    local d rhoP D law CA g vt dt
    entry() { foamDictionary -entry "$2" -value "$1"; }

    cd "$case" || return 1
    # the forces evaluate the cloud's own carrier field
    grep -q "Carrier flow of $Uname: interpolated" "$log" \
        || { echo "FAILED: no carrier flow of the cloud's field $Uname in $log"; return 1; }

    d=$(entry $cloud subModels/injectionModels/bead/sizeDistribution/fixedValueDistribution/value)
    rhoP=$(entry $cloud constantProperties/rho0)
    D=$(entry $cloud $forces/wallCorrectedDrag/pipeDiameter)
    law=$(entry $cloud $forces/wallCorrectedDrag/law)
    CA=$(entry $cloud $forces/riserAddedMass/CA)
    g=$(entry constant/g value | tr -d '()' | awk '{print sqrt($1*$1 + $2*$2 + $3*$3)}')
    vt=$("$tools/terminalVelocity" "$d" "$rhoP" "$rhoF" "$mu" "$g" "$D" "$law") || return 1
    dt=$(entry system/controlDict deltaT)

    "$RISER_PYTHON" - "$d" "$rhoP" "$rhoF" "$mu" "$g" "$CA" "$vt" "$dt" "$tol" <<'PY'
import math, os, sys
from riserfoam import foamfields as ff
d, rhoP, rhoF, mu, g, CA, vt, dt, tol = map(float, sys.argv[1:])
V = math.pi * d ** 3 / 6
W = (rhoP - rhoF) * V * g
Re = rhoF * d * vt / mu
tau = (rhoP + CA * rhoF) * vt / ((rhoP - rhoF) * g)
print("d = %g m, rho_p = %g, rho_f = %.9g kg/m^3: v_t = %.6e m/s, Re_t = %.3f, "
      "tau = %.4e s" % (d, rhoP, rhoF, vt, Re, tau))
if not Re <= 1:
    sys.exit("FAILED: Re_t = %g above 1, outside the linear drag of the closed form" % Re)

times = sorted((t for t in os.listdir(".") if os.path.isdir(t + "/lagrangian")), key=float)
if not times:
    sys.exit("FAILED: no lagrangian output")
failures = 0
for t in times:
    cloud = t + "/lagrangian/kinematicCloud/"
    u = ff.read_vectors(cloud + "U")[0]
    v = vt * (1 - math.exp(-(float(t) + dt) / tau))
    F = lambda name: ff.read_vectors(cloud + "F_" + name)[0]
    errU = max(abs(u[0]), abs(u[1]), abs(-u[2] - v)) / vt
    drag = F("wallCorrectedDrag")
    errF = max(abs(drag[0]), abs(drag[1]), abs(drag[2] - W * v / vt)) / W
    rest = max(abs(c) for name in ("riserAddedMass", "riserFluidStress", "riserSaffmanMeiLift")
               for c in F(name)) / W
    ok = errU < tol and errF < tol and rest < tol
    failures += not ok
    print("t = %-7s u_z = %.6e, closed form %.6e: |error|/v_t = %.2e; drag error/W = %.2e; "
          "forces of a fluid at rest/W = %.2e (tolerance %.0e) %s"
          % (t, u[2], -v, errU, errF, rest, tol, "ok" if ok else "FAILED"))
sys.exit(1 if failures else 0)
PY
}
