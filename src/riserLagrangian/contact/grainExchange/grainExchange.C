/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "grainExchange.H"
#include "IOstreams.H"
#include "riserFoamVersion.H"
#include "DynamicList.H"
#include "FixedList.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::labelListList Foam::nearProcessors
(
    const UList<vector>& x,
    const scalar cutoff,
    const scalar periodLength
)
{
    // each processor's box of centres (empty: lo > hi)
    List<FixedList<vector, 2>> boxes(Pstream::nProcs());
    FixedList<vector, 2>& mine = boxes[Pstream::myProcNo()];
    mine[0] = vector::uniform(VGREAT);
    mine[1] = vector::uniform(-VGREAT);
    for (const vector& p : x)
    {
        mine[0] = min(mine[0], p);
        mine[1] = max(mine[1], p);
    }
    riserCompatibility::allGatherList(boxes);

    labelListList send(Pstream::nProcs());
    forAll(boxes, proc)
    {
        const vector lo = boxes[proc][0] - vector::uniform(cutoff);
        const vector hi = boxes[proc][1] + vector::uniform(cutoff);
        if (proc == Pstream::myProcNo() || lo.x() > hi.x())
        {
            continue;
        }
        DynamicList<label> near;
        forAll(x, i)
        {
            const vector& p = x[i];
            bool inside =
                p.x() >= lo.x() && p.x() <= hi.x()
             && p.y() >= lo.y() && p.y() <= hi.y();
            if (inside)
            {
                bool inZ = false;
                for (const scalar shift : {0.0, periodLength, -periodLength})
                {
                    const scalar z = p.z() + shift;
                    inZ = inZ || (z >= lo.z() && z <= hi.z());
                    if (periodLength <= 0)
                    {
                        break;
                    }
                }
                inside = inZ;
            }
            if (inside)
            {
                near.append(i);
            }
        }
        send[proc].transfer(near);
    }
    return send;
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const grainState& m)
{
    os  << m.key << token::SPACE << m.processor << token::SPACE << m.x
        << token::SPACE << m.xStart << token::SPACE << m.U << token::SPACE
        << m.omega << token::SPACE << m.a << token::SPACE << m.drag
        << token::SPACE << m.Uc << token::SPACE << m.R << token::SPACE
        << m.mEff << token::SPACE << m.mP << token::SPACE << m.inertia
        << token::SPACE << m.F << token::SPACE << m.T << token::SPACE
        << m.touchingWall << token::SPACE << m.wallSpring << token::SPACE
        << m.need;
    return os;
}


Foam::Istream& Foam::operator>>(Istream& is, grainState& m)
{
    is  >> m.key >> m.processor >> m.x >> m.xStart >> m.U >> m.omega >> m.a
        >> m.drag >> m.Uc >> m.R >> m.mEff >> m.mP >> m.inertia >> m.F
        >> m.T >> m.touchingWall >> m.wallSpring >> m.need;
    is.check(FUNCTION_NAME);
    return is;
}


Foam::Ostream& Foam::operator<<(Ostream& os, const grainPairSpring& s)
{
    os  << s.key << token::SPACE << s.other << token::SPACE << s.spring
        << token::SPACE << s.recorded << token::SPACE << s.approachSpeed
        << token::SPACE << s.force;
    return os;
}


Foam::Istream& Foam::operator>>(Istream& is, grainPairSpring& s)
{
    is  >> s.key >> s.other >> s.spring >> s.recorded >> s.approachSpeed >> s.force;
    is.check(FUNCTION_NAME);
    return is;
}


// ************************************************************************* //
