/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "contactLedger.H"
#include "cloudOutputFile.H"
#include "fvMesh.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::OFstream& Foam::contactLedger::table()
{
    if (!table_.valid())
    {
        table_ =
            cloudOutputFile
            (
                mesh_, cloudName_, modelName_, "contacts",
                "# " + modelName_ + ": one completed particle-wall contact a line\n"
                "# velocities relative to the wall [m/s], spin [rad/s], SI units;"
                " J: the wall force's impulse [N s]\n"
                "# origProc origId tStart tEnd duration overlapMax"
                " normalForceMax Uin_x Uin_y Uin_z Uout_x Uout_y Uout_z"
                " omegaIn_x omegaIn_y omegaIn_z omegaOut_x omegaOut_y omegaOut_z"
                " UnIn UnOut J_x J_y J_z\n",
                3   // tEnd: a contact is kept when it ended by the start time
            );
    }
    return table_();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLedger::contactLedger
(
    const fvMesh& mesh,
    const word& cloudName,
    const word& modelName
)
:
    mesh_(mesh),
    cloudName_(cloudName),
    modelName_(modelName),
    pairOverlapMax_(0)
{
    // opened (and, on a restart, continued up to the start time) now, not
    // at the first completed contact: a restart after which no contact
    // ends must not keep the rows after its start
    table();
}


Foam::contactLedger::contactLedger(const contactLedger& ledger)
:
    mesh_(ledger.mesh_),
    cloudName_(ledger.cloudName_),
    modelName_(ledger.modelName_),
    stock_(ledger.stock_),
    lost_(ledger.lost_),
    pairOverlapMax_(ledger.pairOverlapMax_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wallContactRecord* Foam::contactLedger::stockRecord
(
    const labelPair& key,
    const bool start
)
{
    auto iter = stock_.find(key);
    if (iter.found())
    {
        return &(*iter);
    }
    if (!start)
    {
        return nullptr;
    }
    stock_.insert(key, wallContactRecord());
    return &stock_[key];
}


void Foam::contactLedger::wallContactGoesOn
(
    wallContactRecord& e,
    const scalar t,
    const scalar h,
    const scalar overlap,
    const vector& F,
    const scalar normalForce,
    const vector& Urel,
    const vector& n,
    const vector& spin
)
{
    if (!e.active)
    {
        e = wallContactRecord();
        e.active = true;
        e.start = t - h;
        e.overlapMax = overlap;
        e.normalForceMax = normalForce;
        e.velocityIn = Urel;
        e.normalSpeedIn = Urel & n;
        e.spinIn = spin;
        e.normal = n;
        e.impulse = h*F;
        return;
    }
    e.overlapMax = max(e.overlapMax, overlap);
    e.normalForceMax = max(e.normalForceMax, normalForce);
    e.impulse += h*F;
}


void Foam::contactLedger::wallContactEnds
(
    const labelPair& key,
    const wallContactRecord& e,
    contactTrace& trace,
    const scalar t,
    const vector& Uout,
    const vector& n,
    const vector& spin
)
{
    table()
        << key.first() << ' ' << key.second() << ' '
        << e.start << ' ' << t << ' ' << t - e.start << ' '
        << e.overlapMax << ' ' << e.normalForceMax << ' '
        << e.velocityIn.x() << ' ' << e.velocityIn.y() << ' '
        << e.velocityIn.z() << ' '
        << Uout.x() << ' ' << Uout.y() << ' ' << Uout.z() << ' '
        << e.spinIn.x() << ' ' << e.spinIn.y() << ' ' << e.spinIn.z() << ' '
        << spin.x() << ' ' << spin.y() << ' ' << spin.z() << ' '
        << e.normalSpeedIn << ' ' << -(Uout & n) << ' '
        << e.impulse.x() << ' ' << e.impulse.y() << ' ' << e.impulse.z()
        << endl;
    trace.recordWallContact(e.overlapMax, e.normalSpeedIn);
}


void Foam::contactLedger::dropStockRecord(const labelPair& key)
{
    stock_.erase(key);
}


void Foam::contactLedger::handOverStockRecords
(
    const HashSet<labelPair, labelPairHash>& own
)
{
    // each processor's records of particles it no longer holds: key and
    // the record's numbers
    List<List<scalar>> leaving(Pstream::nProcs());
    {
        DynamicList<scalar> rows;
        DynamicList<labelPair> gone;
        forAllConstIters(stock_, iter)
        {
            if (own.found(iter.key()))
            {
                continue;
            }
            gone.append(iter.key());
            const scalarList v = iter.val().numbers();
            if (v.size())
            {
                rows.append(iter.key().first());
                rows.append(iter.key().second());
                rows.append(v);
            }
        }
        for (const labelPair& key : gone)
        {
            stock_.erase(key);
        }
        leaving[Pstream::myProcNo()].transfer(rows);
    }
    riserCompatibility::allGatherList(leaving);

    const label n = 2 + wallContactRecord::size;
    forAll(leaving, proc)
    {
        const List<scalar>& rows = leaving[proc];
        for (label r = 0; proc != Pstream::myProcNo() && r < rows.size(); r += n)
        {
            const labelPair key(label(rows[r]), label(rows[r + 1]));
            if (own.found(key))
            {
                stock_.set
                (
                    key,
                    wallContactRecord::fromNumbers
                    (
                        SubList<scalar>(rows, n - 2, r + 2),
                        "the wall contact in progress handed over"
                    )
                );
            }
        }
    }
}


void Foam::contactLedger::checkInside
(
    const labelPair& key,
    const scalar overlap,
    const scalar R,
    const scalar t
)
{
    if (overlap > R && lost_.insert(key))
    {
        WarningInFunction
            << "particle " << key << " has its centre outside the pipe at t = "
            << t << ": " << overlap - R << " beyond the wall; "
            << lost_.size() << " particle(s) lost so far" << endl;
    }
}


// ************************************************************************* //
