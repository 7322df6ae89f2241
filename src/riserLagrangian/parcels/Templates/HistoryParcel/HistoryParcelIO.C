/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "HistoryParcel.H"
#include "IOstreams.H"
#include "IOField.H"
#include "CompactIOField.H"
#include "vectorFieldIOField.H"
#include "scalarFieldIOField.H"
#include "OStringStream.H"
#include "contactRecords.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class ParcelType>
Foam::string Foam::HistoryParcel<ParcelType>::propertyList_ =
    Foam::HistoryParcel<ParcelType>::propertyList();


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::HistoryParcel<ParcelType>::HistoryParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    history_(emptyHistory()),
    UNode_(Zero),
    historyKnown_(Zero),
    injectionPending_(false),
    subStepEnd_(vector::zero)
{
    if (readFields)
    {
        label steps;
        vector slip0;
        List<vector> window, tail;
        is >> steps >> slip0 >> window >> tail >> UNode_ >> historyKnown_
            >> contacts_.wallContacts >> contacts_.wallOverlapMax
            >> contacts_.wallImpactSpeed >> contacts_.wallEnergy
            >> contacts_.pairContacts >> contacts_.pairImpactSpeed
            >> contacts_.pairEnergy >> contacts_.subStepOffset;
        scalarList wall, pairs;
        is >> wall >> pairs >> subStepEnd_;
        inProgress_.setWall(wall, "A parcel sent between processors");
        inProgress_.setPairs(pairs, "A parcel sent between processors");
        setHistory(steps, slip0, window, tail);
    }

    is.check(FUNCTION_NAME);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class CloudType>
void Foam::HistoryParcel<ParcelType>::checkPlaces(const CloudType& c)
{
    const polyMesh& mesh = c.pMesh();
    label i = 0;
    for (const HistoryParcel<ParcelType>& p : c)
    {
        const label celli = p.cell();
        const label facei = p.tetFace();
        const label pti = p.tetPt();
        const barycentric& b = p.coordinates();
        OStringStream defect;
        if (celli < 0 || celli >= mesh.nCells())
        {
            defect
                << "cell " << celli << ", not a cell of the mesh (0 to "
                << mesh.nCells() - 1 << ")";
        }
        else if (!mesh.cells()[celli].found(facei))
        {
            defect
                << "tetrahedron face " << facei << ", not a face of its cell "
                << celli << " (" << mesh.cells()[celli] << ")";
        }
        else if (pti < 1 || pti > mesh.faces()[facei].size() - 2)
        {
            defect
                << "tetrahedron point " << pti << " of face " << facei
                << ", which has " << mesh.faces()[facei].size()
                << " points (allowed 1 to " << mesh.faces()[facei].size() - 2
                << ")";
        }
        else
        {
            // barycentric coordinates in the tetrahedron: each in [0, 1]
            // and their sum 1, up to the round-off tracking leaves
            const scalar tol = 1e-6;
            bool inside = mag(b.a() + b.b() + b.c() + b.d() - 1) <= tol;
            for (direction k = 0; k < barycentric::nComponents; ++k)
            {
                inside = inside && std::isfinite(b[k]) && b[k] >= -tol && b[k] <= 1 + tol;
            }
            if (!inside)
            {
                defect
                    << "barycentric coordinates " << b << " (allowed: each"
                    << " in [0, 1] and their sum 1, within 1e-6)";
            }
        }
        if (!defect.str().empty())
        {
            const IOobject io(riserCompatibility::cloudFieldIO(c, "coordinates", IOobject::NO_READ));
            FatalErrorInFunction
                << "Cloud " << c.name() << " at time " << c.time().timeName()
                << ": particle " << i << " of " << io.path() << " (the"
                << " coordinates or positions file) holds " << defect.str().c_str()
                << "; it has no place in the mesh of this case. Restore the"
                << " file as written for this mesh." << exit(FatalError);
        }
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::HistoryParcel<ParcelType>::readFields(CloudType& c)
{
    const bool valid = c.size();
    IOobject stepsIO(riserCompatibility::cloudFieldIO(c, "historySteps", IOobject::MUST_READ));
    const bool histories = stepsIO.typeHeaderOk<IOField<label>>(true);

    // the fields of fields (one list per particle) of the riser parcel: a
    // copy of the time without some of them (reconstructPar of v1912 leaves
    // them out when written in ascii and not selected) is refused here,
    // naming the field, rather than wherever its reading fails
    for
    (
        const word name
      : {
            "collisionRecordsPairAccessed", "collisionRecordsPairOrigProcOfOther",
            "collisionRecordsPairOrigIdOfOther", "collisionRecordsPairData",
            "collisionRecordsWallAccessed", "collisionRecordsWallPRel",
            "collisionRecordsWallData", "historyWindow", "historyTail"
        }
    )
    {
        const bool history = name.compare(0, 7, "history") == 0;
        if
        (
            valid && (histories || !history)
         && !isFile(riserCompatibility::cloudFieldIO(c, name, IOobject::MUST_READ).objectPath())
        )
        {
            FatalErrorInFunction
                << "Cloud " << c.name() << " at time " << c.time().timeName()
                << ": " << c.size() << " particles but no field " << name
                << " (" << riserCompatibility::cloudFieldIO(c, name, IOobject::NO_READ).objectPath()
                << "). reconstructPar of OpenFOAM v1912 leaves out the ascii"
                << " fields of fields unless they are selected: run"
                << " reconstructPar -lagrangianFields '(\".*\")'"
                << exit(FatalError);
        }
    }

    // the contact records, checked before the stock reading takes them
    contactRecords::check(c);

    checkPlaces(c);

    ParcelType::readFields(c);

    // the contact trace: zero for a cloud written without it (the wall
    // counts, and the energies with the pair contacts, which came later).
    // One field into each parcel's trace; a group's first field may be
    // absent (false), the others must then be there.
    auto readTrace = [&c, valid](const word& name, auto member, const bool first)
    {
        typedef typename std::decay<decltype(contactTrace().*member)>::type Type;
        IOobject io(riserCompatibility::cloudFieldIO(c, name, IOobject::MUST_READ));
        if (first && !io.template typeHeaderOk<IOField<Type>>(true))
        {
            return false;
        }
        IOField<Type> field(io, valid);
        c.checkFieldIOobject(c, field);
        label i = 0;
        for (HistoryParcel<ParcelType>& p : c)
        {
            p.contacts_.*member = field[i++];
        }
        return true;
    };
    if (readTrace("wallContacts", &contactTrace::wallContacts, true))
    {
        readTrace("wallOverlapMax", &contactTrace::wallOverlapMax, false);
        readTrace("wallImpactSpeed", &contactTrace::wallImpactSpeed, false);
    }
    else if (valid)
    {
        Info<< "    " << c.name() << ": no wall-contact trace written at "
            << c.time().timeName() << "; the counts start there" << endl;
    }
    if (readTrace("wallEnergy", &contactTrace::wallEnergy, true))
    {
        readTrace("pairContacts", &contactTrace::pairContacts, false);
        readTrace("pairImpactSpeed", &contactTrace::pairImpactSpeed, false);
        readTrace("pairEnergy", &contactTrace::pairEnergy, false);
    }
    else if (valid)
    {
        Info<< "    " << c.name() << ": no contact energies or pair-contact"
            << " trace (wallEnergy, pairContacts, pairImpactSpeed,"
            << " pairEnergy) written at " << c.time().timeName()
            << "; they start at zero there" << endl;
    }

    if (!readTrace("subStepOffset", &contactTrace::subStepOffset, true) && valid)
    {
        Info<< "    " << c.name() << ": no subStepOffset written at "
            << c.time().timeName() << "; zero there" << endl;
    }

    // the contacts in progress: none for a cloud written without them
    {
        IOobject wallIO(riserCompatibility::cloudFieldIO(c, "wallContactInProgress", IOobject::MUST_READ));
        if (isFile(wallIO.objectPath()))
        {
            scalarFieldCompactIOField wall(wallIO, valid);
            c.checkFieldFieldIOobject(c, wall);
            scalarFieldCompactIOField pairs
            (
                riserCompatibility::cloudFieldIO(c, "pairContactsInProgress", IOobject::MUST_READ),
                valid
            );
            c.checkFieldFieldIOobject(c, pairs);
            label i = 0;
            for (HistoryParcel<ParcelType>& p : c)
            {
                const string what
                (
                    "Cloud " + c.name() + " at time " + c.time().timeName()
                  + ", particle " + Foam::name(i)
                );
                p.inProgress_.setWall(wall[i], what + " of " + wallIO.objectPath());
                p.inProgress_.setPairs(pairs[i], what + " of " + pairs.objectPath());
                ++i;
            }
        }
        else if (valid)
        {
            Info<< "    " << c.name() << ": no contacts in progress"
                << " (wallContactInProgress, pairContactsInProgress) written"
                << " at " << c.time().timeName() << "; a contact going on"
                << " there is taken as starting there" << endl;
        }
    }

    // clouds written without histories (another solver, or initial
    // particles): each particle starts its history at its next step
    if (valid && !histories)
    {
        Info<< "    " << c.name() << ": no Basset histories written at "
            << c.time().timeName() << "; they start at the next step" << endl;
        return;
    }

    IOField<label> steps(stepsIO, valid);
    c.checkFieldIOobject(c, steps);

    IOField<vector> slip0(riserCompatibility::cloudFieldIO(c, "historySlip0", IOobject::MUST_READ), valid);
    c.checkFieldIOobject(c, slip0);

    vectorFieldCompactIOField window
    (
        riserCompatibility::cloudFieldIO(c, "historyWindow", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, window);

    vectorFieldCompactIOField tail
    (
        riserCompatibility::cloudFieldIO(c, "historyTail", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, tail);

    label i = 0;
    for (HistoryParcel<ParcelType>& p : c)
    {
        p.setHistory(steps[i], slip0[i], window[i], tail[i]);
        // written at the end of a step: the last history node is now
        p.UNode_ = p.U();
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::HistoryParcel<ParcelType>::collectFields
(
    const CloudType& c,
    labelField& steps,
    vectorField& slip0,
    labelField& wallContacts,
    scalarField& wallOverlapMax,
    scalarField& wallImpactSpeed,
    scalarField& wallEnergy,
    labelField& pairContacts,
    scalarField& pairImpactSpeed,
    scalarField& pairEnergy,
    vectorField& subStepOffset
)
{
    label i = 0;
    for (const HistoryParcel<ParcelType>& p : c)
    {
        steps[i] = p.history_.steps;
        slip0[i] = p.history_.slip0;
        const contactTrace& trace = p.contacts_;
        wallContacts[i] = trace.wallContacts;
        wallOverlapMax[i] = trace.wallOverlapMax;
        wallImpactSpeed[i] = trace.wallImpactSpeed;
        wallEnergy[i] = trace.wallEnergy;
        pairContacts[i] = trace.pairContacts;
        pairImpactSpeed[i] = trace.pairImpactSpeed;
        pairEnergy[i] = trace.pairEnergy;
        subStepOffset[i] = trace.subStepOffset;
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::HistoryParcel<ParcelType>::writeFields(const CloudType& c)
{
    ParcelType::writeFields(c);

    const label np = c.size();
    const bool valid = np;

    IOField<label> steps(riserCompatibility::cloudFieldIO(c, "historySteps", IOobject::NO_READ), np);
    IOField<vector> slip0(riserCompatibility::cloudFieldIO(c, "historySlip0", IOobject::NO_READ), np);
    IOField<label> contacts(riserCompatibility::cloudFieldIO(c, "wallContacts", IOobject::NO_READ), np);
    IOField<scalar> overlapMax
    (
        riserCompatibility::cloudFieldIO(c, "wallOverlapMax", IOobject::NO_READ),
        np
    );
    IOField<scalar> impactSpeed
    (
        riserCompatibility::cloudFieldIO(c, "wallImpactSpeed", IOobject::NO_READ),
        np
    );
    IOField<scalar> wallEnergy
    (
        riserCompatibility::cloudFieldIO(c, "wallEnergy", IOobject::NO_READ),
        np
    );
    IOField<label> pairContacts
    (
        riserCompatibility::cloudFieldIO(c, "pairContacts", IOobject::NO_READ),
        np
    );
    IOField<scalar> pairImpactSpeed
    (
        riserCompatibility::cloudFieldIO(c, "pairImpactSpeed", IOobject::NO_READ),
        np
    );
    IOField<scalar> pairEnergy
    (
        riserCompatibility::cloudFieldIO(c, "pairEnergy", IOobject::NO_READ),
        np
    );
    IOField<vector> subStepOffset
    (
        riserCompatibility::cloudFieldIO(c, "subStepOffset", IOobject::NO_READ),
        np
    );
    collectFields
    (
        c, steps, slip0, contacts, overlapMax, impactSpeed, wallEnergy,
        pairContacts, pairImpactSpeed, pairEnergy, subStepOffset
    );

    vectorFieldCompactIOField window
    (
        riserCompatibility::cloudFieldIO(c, "historyWindow", IOobject::NO_READ),
        np
    );
    vectorFieldCompactIOField tail
    (
        riserCompatibility::cloudFieldIO(c, "historyTail", IOobject::NO_READ),
        np
    );

    scalarFieldCompactIOField wallInProgress
    (
        riserCompatibility::cloudFieldIO(c, "wallContactInProgress", IOobject::NO_READ),
        np
    );
    scalarFieldCompactIOField pairsInProgress
    (
        riserCompatibility::cloudFieldIO(c, "pairContactsInProgress", IOobject::NO_READ),
        np
    );

    label i = 0;
    for (const HistoryParcel<ParcelType>& p : c)
    {
        window[i] = p.windowList();
        tail[i] = p.tailList();
        wallInProgress[i] = p.inProgress_.wallNumbers();
        pairsInProgress[i] = p.inProgress_.pairNumbers();
        ++i;
    }

    steps.write(valid);
    slip0.write(valid);
    window.write(valid);
    tail.write(valid);
    contacts.write(valid);
    overlapMax.write(valid);
    impactSpeed.write(valid);
    wallEnergy.write(valid);
    pairContacts.write(valid);
    pairImpactSpeed.write(valid);
    pairEnergy.write(valid);
    subStepOffset.write(valid);
    wallInProgress.write(valid);
    pairsInProgress.write(valid);
}


template<class ParcelType>
template<class CloudType>
void Foam::HistoryParcel<ParcelType>::writeObjects
(
    const CloudType& c,
    objectRegistry& obr
)
{
    ParcelType::writeObjects(c, obr);

    const label np = c.size();
    collectFields
    (
        c,
        cloud::createIOField<label>("historySteps", np, obr),
        cloud::createIOField<vector>("historySlip0", np, obr),
        cloud::createIOField<label>("wallContacts", np, obr),
        cloud::createIOField<scalar>("wallOverlapMax", np, obr),
        cloud::createIOField<scalar>("wallImpactSpeed", np, obr),
        cloud::createIOField<scalar>("wallEnergy", np, obr),
        cloud::createIOField<label>("pairContacts", np, obr),
        cloud::createIOField<scalar>("pairImpactSpeed", np, obr),
        cloud::createIOField<scalar>("pairEnergy", np, obr),
        cloud::createIOField<vector>("subStepOffset", np, obr)
    );
}


template<class ParcelType>
void Foam::HistoryParcel<ParcelType>::writeProperties
(
    Ostream& os,
    const wordRes& filters,
    const word& delim,
    const bool namesOnly
) const
{
    ParcelType::writeProperties(os, filters, delim, namesOnly);

    ParcelType::writeProperty
    (
        os, "historySteps", label(history_.steps), namesOnly, delim, filters
    );
    ParcelType::writeProperty
    (
        os, "historySlip0", history_.slip0, namesOnly, delim, filters
    );
    ParcelType::writeProperty
    (
        os, "wallContacts", contacts_.wallContacts, namesOnly, delim, filters
    );
    ParcelType::writeProperty
    (
        os, "wallOverlapMax", contacts_.wallOverlapMax, namesOnly, delim,
        filters
    );
    ParcelType::writeProperty
    (
        os, "wallImpactSpeed", contacts_.wallImpactSpeed, namesOnly, delim,
        filters
    );
    ParcelType::writeProperty
    (
        os, "wallEnergy", contacts_.wallEnergy, namesOnly, delim, filters
    );
    ParcelType::writeProperty
    (
        os, "pairContacts", contacts_.pairContacts, namesOnly, delim, filters
    );
    ParcelType::writeProperty
    (
        os, "pairImpactSpeed", contacts_.pairImpactSpeed, namesOnly, delim,
        filters
    );
    ParcelType::writeProperty
    (
        os, "pairEnergy", contacts_.pairEnergy, namesOnly, delim, filters
    );
    ParcelType::writeProperty
    (
        os, "subStepOffset", contacts_.subStepOffset, namesOnly, delim,
        filters
    );
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const HistoryParcel<ParcelType>& p
)
{
    os  << static_cast<const ParcelType&>(p)
        << token::SPACE << label(p.history_.steps)
        << token::SPACE << p.history_.slip0
        << token::SPACE << p.windowList()
        << token::SPACE << p.tailList()
        << token::SPACE << p.UNode_
        << token::SPACE << p.historyKnown_
        << token::SPACE << p.contacts_.wallContacts
        << token::SPACE << p.contacts_.wallOverlapMax
        << token::SPACE << p.contacts_.wallImpactSpeed
        << token::SPACE << p.contacts_.wallEnergy
        << token::SPACE << p.contacts_.pairContacts
        << token::SPACE << p.contacts_.pairImpactSpeed
        << token::SPACE << p.contacts_.pairEnergy
        << token::SPACE << p.contacts_.subStepOffset
        << token::SPACE << p.inProgress_.wallNumbers()
        << token::SPACE << p.inProgress_.pairNumbers()
        << token::SPACE << p.subStepEnd_;

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
