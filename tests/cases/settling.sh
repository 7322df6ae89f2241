# Shared by the settling case tests (sourced, not run): run a copy of the
# glass-bead tutorial, optionally modified, and check that the final settling
# speed equals the terminal velocity of the core's weight-drag balance
# (terminalVelocity.cpp) within 0.5%.
#
# settling_case <scratch folder> <folder holding terminalVelocity> <modify>
#   <modify>: a shell function run inside the case after blockMesh, or ':'
# The oracle's inputs are read from the case itself, after the modification.

settling_case()
{
    local work="$1" tools="$2" modify="$3"
    local root case
    root="$(cd "${BASH_SOURCE[0]%/*}/../.." && pwd)"
    case="$root/tutorials/settling/glassBead"
    . "$root/etc/bootstrap" || return 1

    rm -rf "$work" && mkdir -p "$work"
    cp -r "$case/0" "$case/constant" "$case/system" "$work"
    cd "$work" || return 1
    blockMesh > log.blockMesh 2>&1 || return 1
    "$modify" || return 1
    icoUncoupledKinematicParcelFoam > log.icoUncoupledKinematicParcelFoam 2>&1 \
        || { tail -30 log.icoUncoupledKinematicParcelFoam; return 1; }

    entry() { foamDictionary -entry "$2" -value "$1"; }
    local cloud=constant/kinematicCloudProperties
    local forces=subModels/particleForces/wallCorrectedDrag
    local endTime d rhoP D law rhoF nu g mu uz vt
    endTime=$(entry system/controlDict endTime)
    d=$(entry $cloud subModels/injectionModels/bead/sizeDistribution/fixedValueDistribution/value)
    rhoP=$(entry $cloud constantProperties/rho0)
    D=$(entry $cloud $forces/pipeDiameter)
    law=$(entry $cloud $forces/law)
    rhoF=$(entry constant/transportProperties rhoInf)
    nu=$(entry constant/transportProperties nu)
    g=$(entry constant/g value | tr -d '()' | awk '{print sqrt($1*$1 + $2*$2 + $3*$3)}')
    mu=$(awk -v a="$nu" -v b="$rhoF" 'BEGIN {printf "%.17g", a*b}')

    # the one parcel's vertical velocity
    uz=$("$RISER_PYTHON" -c 'import sys; from riserfoam import foamfields
print("%.17g" % foamfields.read_vectors(sys.argv[1])[0][2])' "$endTime/lagrangian/kinematicCloud/U")
    vt=$("$tools/terminalVelocity" "$d" "$rhoP" "$rhoF" "$mu" "$g" "$D" "$law")
    echo "d = $d m, rho_p = $rhoP kg/m^3, D = $D m, law $law:"
    echo "settling speed $uz m/s after $endTime s, terminal velocity of the balance $vt m/s"
    awk -v u="$uz" -v vt="$vt" 'BEGIN {
        err = (-u - vt)/vt; if (err < 0) err = -err
        printf "relative difference %.3e (tolerance 5e-3)\n", err
        exit !(err < 5e-3)
    }'
}
