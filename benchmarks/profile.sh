#!/bin/bash
# Profile of the flagship tutorials/riser/oscillatingContact (riser frame,
# one ore particle, wall contacts, 5 periods, 3,334 steps), as the tutorial
# runs it (its table and force-field output included), on its own mesh
# (riserMesh -n 12, 11,520 cells), under perf (sampling, DWARF call
# stacks). Writes results/profile-flagship.txt: self and inclusive time of
# the top functions, and where the time of the project's own code goes.
# benchmarks/profile.txt is the report written from it.
#
# usage: benchmarks/profile.sh [build folder]   (default build/benchmarks/profile)
cd "${0%/*}" || exit 1
here="$(pwd -P)"
. ../etc/bootstrap || exit 1

if ! command -v perf > /dev/null || ! perf stat -e task-clock true > /dev/null 2>&1
then
    echo "profile.sh: perf missing or not permitted (apt-get install linux-perf); no profile" 1>&2
    exit 0
fi

work="${1:-$RISER_DIR/build/benchmarks/profile}"
case="$work/oscillatingContact"
flagship="$RISER_DIR/tutorials/riser/oscillatingContact"
rm -rf "$case" && mkdir -p "$case"
cp -r "$flagship/0" "$flagship/constant" "$flagship/system" "$case"
rm -rf "$case/constant/polyMesh" "$case/system/blockMeshDict"
"$RISER_DIR/bin/riserMesh" -D 0.1 -L 0.2 -n 12 -ends cyclic -case "$case" > "$case/log.riserMesh"
blockMesh -case "$case" > "$case/log.blockMesh" 2>&1 || exit 1

start=$(date +%s.%N)
perf record -q -o "$work/perf.data" -F 1000 --call-graph dwarf,32768 \
    riserParcelFoam -case "$case" > "$case/log.riserParcelFoam" 2> "$work/perf.log" \
    || { echo "profile.sh: riserParcelFoam failed, see $case/log.riserParcelFoam" 1>&2; exit 1; }
end=$(date +%s.%N)
perf script -i "$work/perf.data" 2> /dev/null > "$work/perf.txt"

out="$here/results/profile-flagship.txt"
mkdir -p "$here/results"
{
    echo "# riserParcelFoam, tutorials/riser/oscillatingContact (as the tutorial runs it: 3,334 steps,"
    echo "# table and force-field output, 33 field writes), perf record -F 1000 --call-graph dwarf"
    echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -1)"
    printf '# run under perf: %.1f s wall; sub-cycled steps: %s\n' \
        "$(echo "$end - $start" | bc)" "$(grep -c 'move-collide subCycles' "$case/log.riserParcelFoam")"
    "$RISER_PYTHON" "$here/perfStacks.py" "$work/perf.txt" 30 --ours
} > "$out"
echo "profile.sh: wrote $out"
