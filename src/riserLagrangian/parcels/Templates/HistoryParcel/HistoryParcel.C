/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "HistoryParcel.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
Foam::List<Foam::vector>
Foam::HistoryParcel<ParcelType>::windowList() const
{
    List<vector> window(history_.window.size());
    forAll(window, j)
    {
        window[j] = history_.at(j);
    }
    return window;
}


template<class ParcelType>
Foam::List<Foam::vector>
Foam::HistoryParcel<ParcelType>::tailList() const
{
    List<vector> tail(label(history_.tail.size()));
    std::copy(history_.tail.begin(), history_.tail.end(), tail.begin());
    return tail;
}


template<class ParcelType>
void Foam::HistoryParcel<ParcelType>::setHistory
(
    const label steps,
    const vector& slip0,
    const List<vector>& window,
    const List<vector>& tail
)
{
    if (tail.size() != historyState::m)
    {
        FatalErrorInFunction
            << "historyTail of a parcel holds " << tail.size()
            << " values instead of " << label(historyState::m)
            << exit(FatalError);
    }
    history_ = emptyHistory();
    history_.steps = steps;
    history_.slip0 = slip0;
    history_.window.assign(window.begin(), window.end());
    std::copy(tail.begin(), tail.end(), history_.tail.begin());
}


template<class ParcelType>
void Foam::HistoryParcel<ParcelType>::transformProperties(const tensor& T)
{
    ParcelType::transformProperties(T);

    history_.slip0 = transform(T, history_.slip0);
    for (vector& g : history_.window)
    {
        g = transform(T, g);
    }
    for (vector& s : history_.tail)
    {
        s = transform(T, s);
    }
    UNode_ = transform(T, UNode_);
    historyKnown_ = transform(T, historyKnown_);
    contacts_.subStepOffset = transform(T, contacts_.subStepOffset);
    if (wallContactRecord* w = inProgress_.wall())
    {
        for (vector* u : {&w->velocityIn, &w->spinIn, &w->force, &w->normal, &w->wallVelocity, &w->impulse})
        {
            *u = transform(T, *u);
        }
    }
    for (pairContactRecord& r : inProgress_.pairs)
    {
        r.force = transform(T, r.force);
    }
    // (the force and torque; the position as the riser's cyclic ends, which
    // are translational, leave it: RiserCloud wraps the offset)
    subStepEnd_[1] = transform(T, subStepEnd_[1]);
    subStepEnd_[2] = transform(T, subStepEnd_[2]);
}


template<class ParcelType>
void Foam::HistoryParcel<ParcelType>::transformProperties
(
    const vector& separation
)
{
    ParcelType::transformProperties(separation);
}


// * * * * * * * * * * * * * * * * * * * IO  * * * * * * * * * * * * * * * * //

#include "HistoryParcelIO.C"

// ************************************************************************* //
