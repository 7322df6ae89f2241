# Shared by the restart case tests (sourced, not run): tiny copies of a
# riser tutorial and their comparison with the uninterrupted run.
#
# restart_case <tutorial> <case> <endTime> <writeInterval>
#   copies tutorials/riser/<tutorial> to <case> on a coarse cyclic O-grid
#   (D = 0.1, L = 0.1, n = 6), ascii output with 17 digits (a restart
#   reads back exactly what was written), with the Basset force of the
#   flagship (window 0.01 s and tail) where the tutorial has none, so that
#   every restart carries histories.
# set_entry <case> <entry> <value>   sets an entry of system/controlDict
# compare_runs <whole> <other> <time> <tolerance> [<lift tolerance>]
#   python/riserfoam/restarts.py: state at <time> and the tables

restart_case()
{
    local tutorial="$RISER_DIR/tutorials/riser/$1" case="$2"
    mkdir -p "$case"
    cp -r "$tutorial/0" "$tutorial/constant" "$tutorial/system" "$case"
    rm -f "$case/system/blockMeshDict"
    "$RISER_DIR/bin/riserMesh" -D 0.1 -L 0.1 -n 6 -ends cyclic -case "$case" > /dev/null
    blockMesh -case "$case" > "$case/log.blockMesh" 2>&1
    grep -q riserBasset "$case/constant/kinematicCloudProperties" \
        || sed -i 's/^\( *\)riserFluidStress;/&\n\1riserBasset { coefficient michaelidesRoig; method windowTail; windowTime 0.01; }/' \
               "$case/constant/kinematicCloudProperties"
    set_entry "$case" writeFormat ascii
    set_entry "$case" writePrecision 17
    set_entry "$case" endTime "$3"
    set_entry "$case" writeInterval "$4"
}

set_entry()
{
    foamDictionary -set "$3" -entry "$2" "$1/system/controlDict" > /dev/null
}

compare_runs()
{
    "$RISER_PYTHON" -m riserfoam.restarts "$@"
}
