/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserFillInjection.H"
#include "checkedEntry.H"
#include "modelEntries.H"
#include "coreVector.H"
#include "distributionModel.H"
#include "cyclicPolyPatch.H"
#include "Random.H"
#include "boundBox.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::RiserFillInjection<CloudType>::fill()
{
    using namespace checkedEntry;
    using constant::mathematical::pi;

    const dictionary& dict = this->coeffDict();
    const polyMesh& mesh = this->owner().mesh();
    const scalar D = carrier_.riser().diameter();
    const scalar R = 0.5*D;

    const scalar Cv = inRange(dict, "solidsFraction", 0, false, 0.5, true);
    const label seed = count(dict, "seed", 0, labelMax);
    const label maxAttempts = count(dict, "maxAttempts", 1, 10000000, 10000);

    // the section: the mesh's extent along the axis; periodic with cyclics
    const boundBox bb(mesh.points(), true);
    const scalar z0 = bb.min().z();
    const scalar L = bb.max().z() - z0;
    bool periodic = false;
    for (const polyPatch& patch : mesh.boundaryMesh())
    {
        periodic = periodic || isA<cyclicPolyPatch>(patch);
    }
    const scalar V = 0.25*pi*D*D*L;

    Random rnd(seed);
    const autoPtr<distributionModel> size
    (
        distributionModel::New(dict.subDict("sizeDistribution"), rnd)
    );
    autoPtr<distributionModel> density;
    if (dict.found("densityDistribution"))
    {
        density = distributionModel::New(dict.subDict("densityDistribution"), rnd);
        if (!(density->minValue() > 0 && density->maxValue() <= 1e5))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'densityDistribution' spans ["
                << density->minValue() << ", " << density->maxValue()
                << "] kg/m^3; ore densities lie in (0, 1e5]"
                << nl << exit(FatalIOError);
        }
    }
    const scalar rho0 =
        density ? 0 : modelEntries::particleDensity(this->owner().constProps().dict());

    const scalar dMax = size->maxValue();
    const scalar gap =
        inRange(dict, "gap", 0, false, 0.1*D, true, 0.01*dMax);
    // the ends of a closed section are walls; a periodic one must not let
    // an ore reach two images of another
    const scalar span = periodic ? 0.5*L : L;
    if (!(size->minValue() > 0 && dMax + 2*gap < min(D, span)))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'sizeDistribution' spans [" << size->minValue()
            << ", " << dMax << "] m; with gap " << gap << " m the ores must"
            << " lie in (0, " << min(D, span) - 2*gap << ") (riser D = " << D
            << " m, section length L = " << L << " m"
            << (periodic ? ", periodic: at most L/2" : "") << ")"
            << nl << exit(FatalIOError);
    }

    // bins at least dMax + gap wide: an ore's neighbours are in the 27 bins
    // about its own
    const scalar h = dMax + gap;
    const label nXY = max(label(1), label(2*R/h));
    const label nZ = max(label(1), label(L/h));
    List<DynamicList<label>> bins(nXY*nXY*nZ);
    auto binIndex = [&](const scalar c, const scalar lo, const scalar width, const label n)
    {
        return min(n - 1, max(label(0), label((c - lo)/width*n)));
    };
    auto binOf = [&](const label ix, const label iy, const label iz)
    {
        return (iz*nXY + iy)*nXY + ix;
    };

    DynamicList<vector> places;
    DynamicList<scalar> diameters, densities;
    const scalar target = Cv*V;
    scalar placed = 0;

    auto isFree = [&](const vector& x, const scalar r)
    {
        const label ix = binIndex(x.x(), -R, 2*R, nXY);
        const label iy = binIndex(x.y(), -R, 2*R, nXY);
        const label iz = binIndex(x.z(), 0, L, nZ);
        labelHashSet zBins;
        for (label dz = -1; dz <= 1; ++dz)
        {
            const label jz = iz + dz;
            if (periodic)
            {
                zBins.insert((jz + nZ) % nZ);
            }
            else if (jz >= 0 && jz < nZ)
            {
                zBins.insert(jz);
            }
        }
        for (const label jz : zBins)
        {
            for (label jy = max(iy - 1, 0); jy <= min(iy + 1, nXY - 1); ++jy)
            {
                for (label jx = max(ix - 1, 0); jx <= min(ix + 1, nXY - 1); ++jx)
                {
                    for (const label j : bins[binOf(jx, jy, jz)])
                    {
                        vector s = x - places[j];
                        if (periodic)
                        {
                            s.z() -= L*std::round(s.z()/L);
                        }
                        const scalar reach = r + 0.5*diameters[j] + gap;
                        if (magSqr(s) < reach*reach)
                        {
                            return false;
                        }
                    }
                }
            }
        }
        return true;
    };

    while (true)
    {
        const scalar d = size->sample();
        const scalar rho = density ? density->sample() : rho0;
        const scalar v = pi/6*pow3(d);
        if (target - placed < 0.5*v)
        {
            break;
        }
        const scalar r = 0.5*d;
        const scalar reachWall = R - r - gap;
        const scalar zLo = periodic ? 0 : r + gap;
        const scalar zSpan = periodic ? L : L - 2*(r + gap);

        bool done = false;
        for (label attempt = 0; attempt < maxAttempts && !done; ++attempt)
        {
            const scalar s = reachWall*std::sqrt(rnd.sample01<scalar>());
            const scalar phi = 2*pi*rnd.sample01<scalar>();
            const vector x
            (
                s*std::cos(phi), s*std::sin(phi), zLo + zSpan*rnd.sample01<scalar>()
            );
            if (isFree(x, r))
            {
                bins
                [
                    binOf
                    (
                        binIndex(x.x(), -R, 2*R, nXY),
                        binIndex(x.y(), -R, 2*R, nXY),
                        binIndex(x.z(), 0, L, nZ)
                    )
                ].append(places.size());
                places.append(x);
                diameters.append(d);
                densities.append(rho);
                placed += v;
                done = true;
            }
        }
        if (!done)
        {
            FatalIOErrorInFunction(dict)
                << "entry 'solidsFraction' = " << Cv << " is beyond what"
                << " random sequential placement reaches here: ore "
                << places.size() + 1 << " (d = " << d << " m) found no place"
                << " in " << maxAttempts << " attempts at C_v = " << placed/V
                << " (equal spheres jam near 0.38); lower solidsFraction"
                << " into (0, " << placed/V << "]" << nl << exit(FatalIOError);
        }
    }
    if (places.empty())
    {
        FatalIOErrorInFunction(dict)
            << "entry 'solidsFraction' = " << Cv << " places no ore: the"
            << " section holds " << V << " m^3 and one ore of diameter "
            << size->meanValue() << " m is "
            << pi/6*pow3(size->meanValue())/V << " of it" << nl
            << exit(FatalIOError);
    }

    places_.transfer(places);
    diameters_.transfer(diameters);
    densities_.transfer(densities);
    z0_ = z0;
    this->volumeTotal_ = placed;

    Info<< "    riserFill: placed " << places_.size() << " ores, solids"
        << " fraction C_v = " << placed/V << " (requested " << Cv
        << ") in the " << (periodic ? "periodic " : "") << "riser section of"
        << " length " << L << " m and volume " << V << " m^3" << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserFillInjection<CloudType>::RiserFillInjection
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    InjectionModel<CloudType>(dict, owner, modelName, typeName),
    carrier_(carrierFlow::New(owner.U())),
    z0_(0),
    carrierVelocity_
    (
        checkedEntry::choice<bool>
        (
            this->coeffDict(), "velocity", {{"carrier", true}, {"fixed", false}}
        )
    ),
    U0_(Zero)
{
    const dictionary& coeffs = this->coeffDict();
    if (carrierVelocity_)
    {
        checkedEntry::allowedKeys
        (
            coeffs,
            {"type", "SOI", "massTotal", "parcelBasisType", "nParticle",
             "solidsFraction", "seed", "velocity", "gap", "maxAttempts",
             "sizeDistribution", "densityDistribution"}
        );
    }
    else
    {
        checkedEntry::allowedKeys
        (
            coeffs,
            {"type", "SOI", "massTotal", "parcelBasisType", "nParticle",
             "solidsFraction", "seed", "velocity", "U0", "gap", "maxAttempts",
             "sizeDistribution", "densityDistribution"}
        );
        U0_ = coeffs.get<vector>("U0");
        if (!modelEntries::withinMagnitude(U0_, 100))
        {
            FatalIOErrorInFunction(coeffs)
                << "entry 'U0' = " << U0_ << " is not a release velocity: its"
                << " magnitude must be finite and at most 100 m/s" << nl
                << exit(FatalIOError);
        }
    }
    if
    (
        this->parcelBasis_ != InjectionModel<CloudType>::pbFixed
     || this->nParticleFixed_ != 1
    )
    {
        FatalIOErrorInFunction(coeffs)
            << "entries 'parcelBasisType' and 'nParticle': riserFill places"
            << " single ores; set parcelBasisType fixed; nParticle 1;"
            << nl << exit(FatalIOError);
    }
    fill();
}


template<class CloudType>
Foam::RiserFillInjection<CloudType>::RiserFillInjection
(
    const RiserFillInjection<CloudType>& im
)
:
    InjectionModel<CloudType>(im),
    carrier_(im.carrier_),
    places_(im.places_),
    z0_(im.z0_),
    diameters_(im.diameters_),
    densities_(im.densities_),
    carrierVelocity_(im.carrierVelocity_),
    U0_(im.U0_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::RiserFillInjection<CloudType>::parcelsToInject
(
    const scalar time0,
    const scalar time1
)
{
    // times relative to SOI: all ores in the step that holds SOI
    return (0 >= time0 && 0 < time1) ? places_.size() : 0;
}


template<class CloudType>
Foam::scalar Foam::RiserFillInjection<CloudType>::volumeToInject
(
    const scalar time0,
    const scalar time1
)
{
    return (0 >= time0 && 0 < time1) ? this->volumeTotal_ : 0;
}


template<class CloudType>
void Foam::RiserFillInjection<CloudType>::setPositionAndCell
(
    const label parcelI,
    const label,
    const scalar,
    vector& position,
    label& cellOwner,
    label& tetFacei,
    label& tetPti
)
{
    // the section about the riser's axis where the mesh is now
    const scalar t = this->owner().mesh().time().value();
    const vector& place = places_[parcelI];
    position =
        fromCore(carrier_.riser().motion().axis(t))
      + vector(place.x(), place.y(), z0_ + place.z());
    this->findCellAtPosition(cellOwner, tetFacei, tetPti, position, true);
}


template<class CloudType>
void Foam::RiserFillInjection<CloudType>::setProperties
(
    const label parcelI,
    const label,
    const scalar,
    typename CloudType::parcelType& parcel
)
{
    parcel.d() = diameters_[parcelI];
    parcel.rho() = densities_[parcelI];
    parcel.U() =
        carrierVelocity_
      ? fromCore
        (
            carrier_.riser().velocity
            (
                toCore(parcel.position()), this->owner().mesh().time().value()
            )
        )
      : U0_;
}


// ************************************************************************* //
