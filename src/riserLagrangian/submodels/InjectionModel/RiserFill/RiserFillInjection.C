/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserFillInjection.H"
#include "boundBox.H"
#include "coreVector.H"
#include "granular/nearPairs.hpp"
#include "IStringStream.H"
#include "OStringStream.H"

#include <algorithm>
#include <sstream>

// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::RiserFillInjection<CloudType>::fill()
{
    oreSource& source = *this->source_;
    using constant::mathematical::pi;

    const dictionary& dict = this->coeffDict();
    const scalar D = this->riser_.flow().diameter();
    const scalar R = 0.5*D;
    // the amount: a solids fraction, or a number of ores
    const bool counted =
        !checkedEntry::firstOfTwo
        (
            dict, "riserFill takes its amount", "solidsFraction",
            "C_v, in (0, 0.5]", "number", "of ores, whole, in [1, 1e8]"
        );
    const scalar Cv =
        counted
      ? 0
      : checkedEntry::inRange(dict, "solidsFraction", 0, false, 0.5, true);
    const label number = counted ? checkedEntry::count(dict, "number", 1, 100000000) : 0;
    const std::string amount =
        counted
      ? "entry 'number' = " + Foam::name(number)
      : "entry 'solidsFraction' = " + Foam::name(Cv);

    // the section: the mesh's extent along the axis; periodic with cyclics
    const riserModel::sectionExtent& section = this->riser_.section();
    const scalar L = section.length;
    const bool periodic = section.periodic;
    const scalar V = section.volume;

    // the ends of a closed section are walls; a periodic one must not let
    // an ore reach two images of another
    const scalar gap = source.gap();
    source.checkDiameters
    (
        dict, min(D, periodic ? 0.5*L : L) - 2*gap,
        "riser D = " + Foam::name(D) + " m, section length L = "
      + Foam::name(L) + " m" + (periodic ? ", periodic: at most L/2" : "")
    );

    // bins at least dMax + gap wide: an ore's neighbours are in the 27 bins
    // about its own
    const scalar h = source.maxDiameter() + gap;
    const label nXY = max(label(1), label(2*R/h));
    const label nZ = max(label(1), label(L/h));
    List<DynamicList<label>> bins(nXY*nXY*nZ);
    auto binIndex = [](const scalar c, const scalar lo, const scalar width, const label n)
    {
        return min(n - 1, max(label(0), label((c - lo)/width*n)));
    };
    auto binOf = [&](const vector& x)
    {
        return
            (binIndex(x.z(), 0, L, nZ)*nXY + binIndex(x.y(), -R, 2*R, nXY))*nXY
          + binIndex(x.x(), -R, 2*R, nXY);
    };

    // the ores placed so far: z along the section, from its start
    DynamicList<vector>& places = this->places_;
    const DynamicList<scalar>& diameters = this->diameters_;
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
                    for (const label j : bins[(jz*nXY + jy)*nXY + jx])
                    {
                        const vector s =
                            fromCore
                            (
                                riser::nearestImage
                                (
                                    toCore(x - places[j]), section.period()
                                )
                            );
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
        if (counted && places.size() == number)
        {
            break;
        }
        const oreSource::ore o = source.draw();
        if (!counted && target - placed < 0.5*o.volume())
        {
            break;
        }
        const scalar r = 0.5*o.d;
        const scalar zLo = periodic ? 0 : r + gap;
        const scalar zSpan = periodic ? L : L - 2*(r + gap);

        bool done = false;
        for (label attempt = 0; attempt < source.maxAttempts() && !done; ++attempt)
        {
            vector x = source.discPoint(o.d);
            x.z() = zLo + zSpan*source.uniform01();
            if (isFree(x, r))
            {
                bins[binOf(x)].append(places.size());
                this->addOre(x, o);
                placed += o.volume();
                done = true;
            }
        }
        if (!done)
        {
            FatalIOErrorInFunction(dict)
                << amount.c_str() << " is beyond what random sequential"
                << " placement reaches here: ore " << places.size() + 1
                << " (d = " << o.d << " m) found no place in "
                << source.maxAttempts() << " attempts at C_v = " << placed/V
                << " (equal spheres jam near 0.38); lower ";
            if (counted)
            {
                FatalIOError << "number to at most " << places.size();
            }
            else
            {
                FatalIOError << "solidsFraction into (0, " << placed/V << "]";
            }
            FatalIOError << nl << exit(FatalIOError);
        }
    }
    if (places.empty())
    {
        const scalar d = source.meanDiameter();
        FatalIOErrorInFunction(dict)
            << amount.c_str() << " places no ore: the"
            << " section holds " << V << " m^3 and one ore of diameter "
            << d << " m is " << pi/6*pow3(d)/V << " of it" << nl
            << exit(FatalIOError);
    }

    // the places' heights from the riser's axis point
    for (vector& x : places)
    {
        x.z() += section.z0;
    }
    this->volumeTotal_ = placed;

    // what a restart after the fill checks its entries against (on one
    // line, numbers to 15 digits as compared there)
    OStringStream entries;
    entries.precision(15);
    dict.write(entries, false);
    std::string line = entries.str();
    std::replace(line.begin(), line.end(), '\n', ' ');
    this->setModelProperty("fillEntries", string(line));
    this->setModelProperty("fillOres", places.size());
    this->setModelProperty("fillSolidsFraction", placed/V);

    Info<< "    riserFill: placed " << places.size() << " ores, solids"
        << " fraction C_v = " << placed/V << " (requested ";
    if (counted)
    {
        Info<< number << " ores";
    }
    else
    {
        Info<< Cv;
    }
    Info<< ") in the " << (periodic ? "periodic " : "") << "riser section of"
        << " length " << L << " m and volume " << V << " m^3" << endl;
}


template<class CloudType>
void Foam::RiserFillInjection<CloudType>::checkFillMade() const
{
    const dictionary& dict = this->coeffDict();
    const Time& time = this->owner().db().time();
    const fileName record = this->owner().outputProperties().objectPath();
    const string stored = this->template getModelProperty<string>("fillEntries", string());
    if (stored.empty())
    {
        const scalar added =
            this->template getModelProperty<scalar>("parcelsAddedTotal", 0);
        if (added <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "entry 'SOI' = " << this->SOI_ << ": the fill is made in"
                << " the step that holds SOI, before the start time "
                << time.timeName() << ", and the run that wrote "
                << time.timeName() << " made none (no parcels added by"
                << " injector '" << this->modelName() << "' in " << record
                << "): it would never be made." << nl
                << "Set SOI to the start time or later to fill then, or start"
                << " from a time before SOI." << exit(FatalIOError);
        }
        Info<< "    riserFill: the fill made in the step that holds SOI = "
            << this->SOI_ << " (" << added << " ores) is in the cloud read at "
            << time.timeName() << "; nothing more to place (the run that wrote"
            << " it did not record its entries: a change of them is not"
            << " checked)" << endl;
        return;
    }

    // every entry as the fill was made with it
    IStringStream is(stored);
    const dictionary made(is);
    wordList keys(dict.toc());
    for (const word& key : made.toc())
    {
        if (!keys.found(key))
        {
            keys.append(key);
        }
    }
    Foam::sort(keys);
    // an entry's value as written, on one line (none: "no entry")
    auto text = [](const dictionary& d, const word& key) -> std::string
    {
        const entry* e = d.findEntry(key, keyType::LITERAL);
        if (!e)
        {
            return "no entry";
        }
        OStringStream os;
        os.precision(15);
        e->write(os);
        std::string value;
        std::istringstream words(os.str());
        std::string w;
        words >> w;
        while (words >> w)
        {
            value += (value.empty() ? "" : " ") + w;
        }
        if (!e->isDict() && !value.empty() && value.back() == ';')
        {
            value.pop_back();
        }
        return value;
    };
    const label ores = this->template getModelProperty<label>("fillOres", 0);
    const scalar Cv = this->template getModelProperty<scalar>("fillSolidsFraction", 0);
    for (const word& key : keys)
    {
        const std::string now = text(dict, key);
        const std::string then = text(made, key);
        if (now != then)
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << key << "' changed at a restart: " << now.c_str()
                << " here, " << then.c_str() << " in the fill made in the step"
                << " that holds SOI = " << this->SOI_ << " (" << ores
                << " ores, C_v = " << Cv << "; recorded in " << record
                << "). The fill is made once: the cloud read at "
                << time.timeName() << " holds its ores, and a fill changed now"
                << " would place none." << nl
                << "Restore the entry as it was, or start from a time before"
                << " SOI (the fill is then made anew, with the entries as they"
                << " are)." << exit(FatalIOError);
        }
    }
    Info<< "    riserFill: the fill made in the step that holds SOI = "
        << this->SOI_ << ", " << ores << " ores at C_v = " << Cv << ", is in the"
        << " cloud read at " << time.timeName() << "; nothing more to place"
        << endl;
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
    RiserOreInjection<CloudType>
    (
        dict, owner, modelName, typeName, {"solidsFraction", "number"}
    )
{
    // the fill is made in the step that holds SOI: on a restart after it,
    // the cloud read holds its ores
    if (this->SOI_ < owner.db().time().value())
    {
        checkFillMade();
    }
    else
    {
        fill();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::RiserFillInjection<CloudType>::parcelsToInject
(
    const scalar time0,
    const scalar time1
)
{
    // times relative to SOI: all ores in the step that holds SOI
    return (0 >= time0 && 0 < time1) ? this->places_.size() : 0;
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


// ************************************************************************* //
