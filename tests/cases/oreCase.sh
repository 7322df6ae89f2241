# Shared by the ore case tests (sourced, not run): a riser case of ores
# released by one injector. The stationary tutorial's system and transport,
# an O-grid riser (D = 0.1 m, L = 0.2 m, bin/riserMesh) and the cloud
# written here. Ends 'cyclic': a periodic riser section; 'open': the ends
# are the inlet (bottom) and the outlet (top), plain patches through which
# ores leave (stock localInteraction, escape).
#
# ore_case <case folder> <cells across the core> <riserProperties body>
#          <particle forces> <injector entries> [cyclic|open]
# The folder is made afresh; the mesh is built; nothing is run.

ore_case()
{
    local dir="$1" n="$2" riser="$3" forces="$4" injector="$5" ends="${6:-cyclic}"
    local root interaction='standardWallInteraction; standardWallInteractionCoeffs { type rebound; }'
    [ "$ends" = open ] && interaction='localInteraction; localInteractionCoeffs { patches ( riserWall { type rebound; } bottom { type escape; } top { type escape; } ); }'

    root="$(cd "${BASH_SOURCE[0]%/*}/../.." && pwd)"
    rm -rf "$dir" && mkdir -p "$dir"
    cp -r "$root/tutorials/riser/stationary/0" "$root/tutorials/riser/stationary/system" "$dir"
    mkdir -p "$dir/constant"
    cp "$root/tutorials/riser/stationary/constant/g" \
       "$root/tutorials/riser/stationary/constant/transportProperties" "$dir/constant"
    (
        cd "$dir" || exit 1
        "$root/bin/riserMesh" -D 0.1 -L 0.2 -n "$n" -ends "${ends/open/wall}" > log.riserMesh 2>&1 || exit 1
        blockMesh > log.blockMesh 2>&1 || exit 1
        if [ "$ends" = open ]
        then
            for patch in bottom top
            do
                foamDictionary constant/polyMesh/boundary -entry "entry0/$patch/type" -set patch > /dev/null
                foamDictionary constant/polyMesh/boundary -entry "entry0/$patch/inGroups" -remove > /dev/null
                foamDictionary 0/U -entry "boundaryField/$patch" -set '{ type fixedValue; value uniform (0 0 0); }' > /dev/null
            done
        fi
        printf 'FoamFile { version 2.0; format ascii; class dictionary; object riserProperties; }\n%s\n' \
            "$riser" > constant/riserProperties
        cat > constant/kinematicCloudProperties <<CLOUD
FoamFile { version 2.0; format ascii; class dictionary; object kinematicCloudProperties; }
solution
{
    active          true;
    coupled         false;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;
    interpolationSchemes { rho cell; U cellPoint; mu cell; }
    integrationSchemes { U Euler; }
}
constantProperties { rho0 2000; youngsModulus 6e10; poissonsRatio 0.26; }
subModels
{
    particleForces
    {
$forces
    }
    injectionModels
    {
        ores
        {
            SOI             0;
            massTotal       0;
            parcelBasisType fixed;
            nParticle       1;
$injector
        }
    }
    dispersionModel none;
    patchInteractionModel $interaction
    surfaceFilmModel none;
    stochasticCollisionModel none;
    collisionModel  riserContact;
    riserContactCoeffs
    {
        wall { youngsModulus 2e11; poissonsRatio 0.3; }
        normalRestitution       0.76;
        tangentialRestitution   0.7;
        friction                0.2;
        normalForce             tensionAllowed;
        rotation                off;
        stepsPerContact         40;
    }
}
cloudFunctions { forces { type particleForceFields; } }
CLOUD
    )
}
