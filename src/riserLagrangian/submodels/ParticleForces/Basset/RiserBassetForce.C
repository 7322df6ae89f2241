/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "RiserBassetForce.H"
#include "checkedEntry.H"
#include "particleForceEvaluation.H"
#include "IOField.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
riser::HistoryKernel Foam::RiserBassetForce<CloudType>::readKernel
(
    const dictionary& coeffs,
    const scalar deltaT
)
{
    checkedEntry::allowedKeys
    (
        coeffs, {"coefficient", "kernel", "method", "tail", "windowTime"}
    );
    const riser::HistoryKernelLaw law = checkedEntry::choiceOrDefault
    (
        coeffs, "kernel",
        {{"classical", riser::HistoryKernelLaw::classical},
         {"meiAdrian", riser::HistoryKernelLaw::meiAdrian}},
        riser::HistoryKernelLaw::classical
    );
    if (law == riser::HistoryKernelLaw::meiAdrian)
    {
        // the finite-Re kernel is the classical coefficient's, its tail
        // fitted to it
        if (coeffs.get<word>("coefficient") != "classical")
        {
            FatalIOErrorInFunction(coeffs)
                << typeName << ": entry 'coefficient' = "
                << coeffs.get<word>("coefficient") << " with 'kernel meiAdrian':"
                << " the finite-Re kernel holds its own Re dependence on the"
                << " classical coefficient C_H = 6. Use 'coefficient classical;'"
                << " with it, or 'kernel classical;'." << exit(FatalIOError);
        }
        if (coeffs.found("tail"))
        {
            FatalIOErrorInFunction(coeffs)
                << typeName << ": entry 'tail' with 'kernel meiAdrian': the"
                << " tail's constants belong to the classical kernel; the"
                << " finite-Re kernel's tail is fitted to it at each Re."
                << " Remove 'tail'." << exit(FatalIOError);
        }
    }
    const riser::HistoryMethod method =
        checkedEntry::choiceOrDefault
        (
            coeffs, "method",
            {{"windowTail", riser::HistoryMethod::windowTail},
             {"fullHistory", riser::HistoryMethod::fullHistory}},
            riser::HistoryMethod::windowTail
        );

    const riser::HistoryTail tail =
        checkedEntry::choiceOrDefault
        (
            coeffs, "tail",
            {{"vanHinsberg2011", riser::HistoryTail::vanHinsberg2011},
             {"leastSquares", riser::HistoryTail::leastSquares}},
            riser::HistoryTail::vanHinsberg2011
        );

    label window = 0;
    if (method == riser::HistoryMethod::windowTail)
    {
        // at least two flow steps: the window holds the slab that leaves it
        const scalar windowTime =
            checkedEntry::inRange
            (
                coeffs, "windowTime", 2*deltaT, true, 1e5*deltaT, true
            );
        window = label(std::lround(windowTime/deltaT));
    }
    return riser::HistoryKernel(method, deltaT, window, tail, law);
}


template<class CloudType>
void Foam::RiserBassetForce<CloudType>::checkStoredHistories()
{
    CloudType& cloud = this->owner();
    const Time& time = this->mesh().time();
    const scalar deltaT = time.deltaTValue();

    // what the histories depend on (readKernel has checked the entries)
    dictionary settings;
    settings.add("method", word(kernel_.windowed() ? "windowTail" : "fullHistory"));
    settings.add("deltaT", deltaT);
    if (kernel_.windowed())
    {
        settings.add("windowTime", kernel_.window()*deltaT);
        settings.add
        (
            "tail",
            this->coeffs().template lookupOrDefault<word>("tail", "vanHinsberg2011")
        );
    }

    dictionary& stored = cloud.outputProperties().subDictOrAdd(typeName);
    const bool historiesWritten =
        riserCompatibility::cloudFieldIO(cloud, "historySteps", IOobject::MUST_READ)
       .template typeHeaderOk<IOField<label>>(true);
    if (historiesWritten && stored.found("method"))
    {
        // the method first: the other entries belong to it
        for (const word key : {"method", "deltaT", "windowTime", "tail"})
        {
            if (!stored.found(key) || !settings.found(key))
            {
                continue;
            }
            const bool real = key == "deltaT" || key == "windowTime";
            auto text = [&](const dictionary& d)
            {
                return real ? Foam::name(d.get<scalar>(key)) : d.get<word>(key);
            };
            const bool same =
                real
              ? mag(stored.get<scalar>(key) - settings.get<scalar>(key))
                <= 1e-9*settings.get<scalar>(key)
              : stored.get<word>(key) == settings.get<word>(key);
            if (!same)
            {
                FatalIOErrorInFunction(this->coeffs())
                    << typeName << ": entry '" << key << "' = "
                    << text(settings)
                    << (key == "deltaT" ? " (system/controlDict)" : "")
                    << " differs from " << text(stored)
                    << ", the value the Basset histories written at "
                    << time.timeName() << " were built with ("
                    << cloud.outputProperties().objectPath() << "), and they"
                    << " cannot be converted exactly." << nl
                    << "Keep " << text(stored) << ", or restart"
                    << " without the histories (remove the history* fields of "
                    << time.timeName() << ": each particle's history then"
                    << " starts at the next step)." << exit(FatalIOError);
            }
        }
    }
    stored.clear();
    stored.merge(settings);
}


template<class CloudType>
void Foam::RiserBassetForce<CloudType>::checkReadHistories() const
{
    const CloudType& cloud = this->owner();
    auto finite = [](const vector& v)
    {
        return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
    };
    label i = 0;
    for (const auto& p : cloud)
    {
        const auto& h = p.history();
        std::string defect = kernel_.defect(h);
        if (defect.empty())
        {
            bool allFinite = finite(h.slip0);
            for (const vector& g : h.window) allFinite = allFinite && finite(g);
            for (const vector& s : h.tail) allFinite = allFinite && finite(s);
            if (!allFinite)
            {
                defect = "a value that is not a finite number";
            }
        }
        if (!defect.empty())
        {
            FatalErrorInFunction
                << typeName << ": the Basset history of particle " << i
                << " (origProcId " << p.origProc() << ", origId "
                << p.origId() << ") read from " << unchecked_
                << " (historySteps, historySlip0, historyWindow, historyTail)"
                << " holds " << defect.c_str() << ", which the "
                << (kernel_.windowed() ? "windowTail" : "fullHistory")
                << " history of this run cannot continue." << nl
                << "Restore the fields as written, or restart without the"
                << " histories (remove the history* fields from that folder:"
                << " each particle's history then starts at the next step)."
                << exit(FatalError);
        }
        ++i;
    }
}


template<class CloudType>
Foam::scalar Foam::RiserBassetForce<CloudType>::historyCoefficient
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar muc
) const
{
    coefficientCache& c = lastCoefficient_;
    const bool sameState = c.key.matchOrTake(p, this->mesh().time().timeIndex());
    const scalar d = p.d();
    if (sameState && c.U == p.U() && c.muc == muc && c.d == d)
    {
        return c.KH;
    }
    c.U = p.U();
    c.muc = muc;
    c.d = d;

    const scalar rhoc = td.rhoc();
    scalar CH = riser::classicalBassetCoefficient;
    if (coefficient_ == riser::BassetModel::michaelidesRoig)
    {
        const scalar Re =
            rhoc*d*mag(carrier_.velocity(p, td.Uc()) - p.U())/muc;
        CH = riser::bassetCoefficient
        (
            coefficient_, Re, frequency_, strouhalFactor(muc, rhoc, d)
        );
    }
    c.KH = CH*0.25*d*d*std::sqrt(constant::mathematical::pi*rhoc*muc);
    return c.KH;
}


template<class CloudType>
Foam::scalar Foam::RiserBassetForce<CloudType>::ageScale
(
    const typename CloudType::parcelType& p,
    const vector& Uc,
    const scalar rhoc,
    const scalar muc
) const
{
    if (kernel_.law() == riser::HistoryKernelLaw::classical)
    {
        return HUGE_VAL;
    }
    const scalar d = p.d();
    const scalar Re = rhoc*d*mag(carrier_.velocity(p, Uc) - p.U())/muc;
    return riser::meiAdrianAgeScale(Re, d*d*rhoc/muc);
}


template<class CloudType>
Foam::scalar Foam::RiserBassetForce<CloudType>::strouhalFactor
(
    const scalar muc,
    const scalar rhoc,
    const scalar d
) const
{
    strouhalCache& c = lastStrouhal_;
    if (!(muc == c.muc && rhoc == c.rhoc && d == c.d))
    {
        const scalar factor =
            frequency_ > 0
          ? riser::bassetStrouhalFactor(muc, rhoc, 0.5*d, frequency_)
          : 0;
        c = strouhalCache{muc, rhoc, d, factor};
    }
    return c.factor;
}


template<class CloudType>
void Foam::RiserBassetForce<CloudType>::notStarted() const
{
    FatalErrorInFunction
        << "riserBasset: the step at t = " << this->mesh().time().value()
        << " was not started by the cloud; the Basset force needs the riser"
        << " cloud (riserParcelFoam), which advances the histories"
        << exit(FatalError);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RiserBassetForce<CloudType>::RiserBassetForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    carrier_(carrierFlow::ofCloud(owner)),
    coefficient_
    (
        checkedEntry::choice<riser::BassetModel>
        (
            this->coeffs(), "coefficient",
            {{"classical", riser::BassetModel::classical},
             {"michaelidesRoig", riser::BassetModel::michaelidesRoig}}
        )
    ),
    frequency_
    (
        coefficient_ == riser::BassetModel::michaelidesRoig
      ? riserModel::New(mesh).angularFrequency
        (
            this->coeffs(), "coefficient michaelidesRoig"
        )/constant::mathematical::twoPi
      : 0
    ),
    kernel_(readKernel(this->coeffs(), mesh.time().deltaTValue())),
    stepOpen_(false),
    endedTime_(-GREAT),
    unchecked_(riserCompatibility::cloudFieldIO(owner, "historySteps", IOobject::NO_READ).path())
{
    checkStoredHistories();
}


template<class CloudType>
Foam::RiserBassetForce<CloudType>::RiserBassetForce
(
    const RiserBassetForce<CloudType>& f
)
:
    ParticleForce<CloudType>(f),
    carrier_(f.carrier_),
    coefficient_(f.coefficient_),
    frequency_(f.frequency_),
    kernel_(f.kernel_),
    stepOpen_(f.stepOpen_),
    endedTime_(f.endedTime_),
    unchecked_(f.unchecked_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RiserBassetForce<CloudType>::cacheFields(const bool store)
{
    const dictionary& schemes = this->owner().solution().interpolationSchemes();
    carrier_.cacheMaterialDerivative(store, schemes);
    carrier_.cacheVelocityChange(store, schemes);
}


template<class CloudType>
void Foam::RiserBassetForce<CloudType>::startStep()
{
    const Time& time = this->mesh().time();
    stepOpen_ = true;
    if (!unchecked_.empty())
    {
        checkReadHistories();
        unchecked_.clear();
    }

    const scalar h = kernel_.step();
    if (mag(time.deltaTValue() - h) > 1e-10*h)
    {
        FatalErrorInFunction
            << "riserBasset: the history's step is the flow step deltaT = "
            << h << " s, set at start; deltaT is now " << time.deltaTValue()
            << " s. Keep deltaT constant (adjustTimeStep no;)."
            << exit(FatalError);
    }

    // the finite-Re kernel's s* from each particle's slip now: the carrier
    // at the particles (a tracking data, its interpolations a pass over the
    // mesh)
    CloudType& cloud = this->owner();
    autoPtr<typename CloudType::parcelType::trackingData> td;
    if (kernel_.law() == riser::HistoryKernelLaw::meiAdrian)
    {
        td.reset(new typename CloudType::parcelType::trackingData(cloud));
    }

    // the next particle's history is fetched while this one's is summed
    for (auto iter = cloud.begin(); iter != cloud.end(); )
    {
        auto& p = *iter;
        if (++iter != cloud.end())
        {
            kernel_.prefetch(iter->history());
        }
        if (p.historyStarted())
        {
            scalar sStar = HUGE_VAL;
            if (td.valid())
            {
                p.setCellValues(cloud, *td);
                sStar = ageScale(p, td->Uc(), td->rhoc(), td->muc());
            }
            p.historyKnown() = kernel_.knownPart(p.history(), sStar);
        }
    }
}


template<class CloudType>
void Foam::RiserBassetForce<CloudType>::endStep()
{
    const Time& time = this->mesh().time();
    if (!stepOpen_)
    {
        notStarted();
    }
    stepOpen_ = false;
    endedTime_ = time.value();

    CloudType& cloud = this->owner();
    // the carrier at a particle not evaluated in the step: a tracking data
    // (its interpolations a pass over the mesh) made only if one is met
    autoPtr<typename CloudType::parcelType::trackingData> td;
    const scalar dt = time.deltaTValue();

    for (auto& p : cloud)
    {
        const endOfStep<typename CloudType::parcelType> done(p);
        const vector g =
            carrier_.materialDerivative(p, dt) - (p.U() - p.UNode())/dt;
        if (p.historyStarted())
        {
            kernel_.push(p.history(), g);
        }
        else if (p.historyReleased())
        {
            p.history() = kernel_.released(p.history().slip0, g);
        }
        else
        {
            // never evaluated in this step: start now, without a slope
            if (!td.valid())
            {
                td.reset(new typename CloudType::parcelType::trackingData(cloud));
            }
            p.setCellValues(cloud, *td);
            const vector w0 = carrier_.velocity(p, td->Uc()) - p.U();
            p.history() = kernel_.start(w0, vector(Zero));
        }
        p.UNode() = p.U();
    }
}


template<class CloudType>
Foam::forceSuSp Foam::RiserBassetForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    const bool afterStep =
        !stepOpen_ && this->mesh().time().value() == endedTime_;
    if (!stepOpen_ && !afterStep)
    {
        notStarted();
    }
    const scalar KH = historyCoefficient(p, td, td.muc());
    if (!p.historyStarted())
    {
        // released in this step: the history starts at the step's start
        if (!p.historyReleased())
        {
            p.recordRelease(carrier_.velocity(p, td.Uc()) - p.U());
        }
        return forceSuSp
        (
            KH*
            (
                kernel_.firstKnownPart
                (
                    p.history().slip0, ageScale(p, td.Uc(), td.rhoc(), td.muc())
                )
              + kernel_.firstWeight()*carrier_.materialDerivative(p, dt)
            ),
            0
        );
    }
    if (afterStep)
    {
        // after the step (output): the whole force at the end of the step
        // (none for a history that starts now)
        return forceSuSp
        (
            p.history().steps > 0
          ? KH*kernel_.value(p.history(), ageScale(p, td.Uc(), td.rhoc(), td.muc()))
          : vector(Zero),
            0
        );
    }
    return forceSuSp
    (
        KH*(p.historyKnown() + kernel_.newestWeight()*carrier_.materialDerivative(p, dt)),
        0
    );
}


template<class CloudType>
Foam::scalar Foam::RiserBassetForce<CloudType>::massAdd
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar mass
) const
{
    if (!stepOpen_)
    {
        // after the step (output): no step to be implicit in
        return 0;
    }
    return
        historyCoefficient(p, td, td.muc())
       *(p.historyStarted() ? kernel_.newestWeight() : kernel_.firstWeight());
}


// ************************************************************************* //
