/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "grainExchange.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const grainState& m)
{
    os  << m.key << token::SPACE << m.processor << token::SPACE << m.x
        << token::SPACE << m.xStart << token::SPACE << m.U << token::SPACE
        << m.omega << token::SPACE << m.a << token::SPACE << m.drag
        << token::SPACE << m.Uc << token::SPACE << m.R << token::SPACE
        << m.mEff << token::SPACE << m.mP << token::SPACE << m.inertia
        << token::SPACE << m.F << token::SPACE << m.T << token::SPACE
        << m.touchingWall << token::SPACE << m.wallSpring;
    return os;
}


Foam::Istream& Foam::operator>>(Istream& is, grainState& m)
{
    is  >> m.key >> m.processor >> m.x >> m.xStart >> m.U >> m.omega >> m.a
        >> m.drag >> m.Uc >> m.R >> m.mEff >> m.mP >> m.inertia >> m.F
        >> m.T >> m.touchingWall >> m.wallSpring;
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
