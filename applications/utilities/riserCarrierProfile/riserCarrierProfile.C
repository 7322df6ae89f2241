/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later

Application
    riserCarrierProfile

Group
    riserFoam/utilities

Description
    The mean flow of a riser case's computed carrier as a profile about the
    riser's axis, for the one-way solvers' analytic carrier (riserProperties
    'profile tabulated'): writes constant/riserCarrierProfile, rows
    (r w k nu_t) from the axis to the wall, of the axial speed U_z, the
    turbulent kinetic energy k and the eddy viscosity nut of the fields of
    one time (a precursor run of riserCoupledFoam with a RAS model and no
    ores, or any RAS run on a riser mesh).

    The cells are put in bins of equal width in their distance from the
    riser's axis at that time (constant/riserProperties; in the riser's
    frame the axis is the z axis); each bin's row is the volume-weighted
    mean of its cells' radius and fields (empty bins are left out). The
    axis' row continues the two innermost bins as an even function,
    v(r) = a + b r^2; the wall's row is the no-slip wall's: w, k and nu_t
    zero. Prints the rows.

Usage
    riserCarrierProfile [-time t | -latestTime] [-bins n]

    -bins   number of bins across the radius, [3, 1000] (default 10)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "riserModel.H"
#include "coreVector.H"
#include "timeSelector.H"
#include "IOdictionary.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A field of the time, which the profile needs
template<class Type>
Foam::tmp<Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>> readField
(
    const Foam::fvMesh& mesh,
    const Foam::word& name
)
{
    using namespace Foam;
    IOobject io(name, mesh.time().timeName(), mesh, IOobject::MUST_READ);
    if (!io.typeHeaderOk<GeometricField<Type, fvPatchField, volMesh>>(true))
    {
        FatalErrorInFunction
            << "no field " << name << " at time " << mesh.time().timeName()
            << ": the profile takes U, k and nut of a run with a RAS model"
            << exit(FatalError);
    }
    return tmp<GeometricField<Type, fvPatchField, volMesh>>::New(io, mesh);
}


//- The volume-weighted means of the cells in bins of equal width in their
//  distance from the riser's axis at time t: rows (r w k nu_t) of the
//  bins that hold cells, from the axis out (sums over every processor)
Foam::List<Foam::FixedList<Foam::scalar, 4>> binnedMeans
(
    const Foam::fvMesh& mesh,
    const riser::RiserFlow& flow,
    const Foam::scalar t,
    const Foam::label nBins
)
{
    using namespace Foam;
    const volVectorField U(readField<vector>(mesh, "U"));
    const volScalarField k(readField<scalar>(mesh, "k"));
    const volScalarField nut(readField<scalar>(mesh, "nut"));
    // per bin: volume, and the volume-weighted sums of r, w, k, nu_t
    List<FixedList<scalar, 5>> sums(nBins, FixedList<scalar, 5>(Zero));
    forAll(mesh.C(), celli)
    {
        const scalar r =
            mag(fromCore(flow.motion().radialOffset(toCore(mesh.C()[celli]), t)));
        FixedList<scalar, 5>& s = sums[min(label(r/flow.radius()*nBins), nBins - 1)];
        const scalar V = mesh.V()[celli];
        s[0] += V;
        s[1] += V*r;
        s[2] += V*U[celli].z();
        s[3] += V*k[celli];
        s[4] += V*nut[celli];
    }
    List<FixedList<scalar, 4>> rows;
    for (FixedList<scalar, 5>& s : sums)
    {
        for (scalar& v : s)
        {
            reduce(v, sumOp<scalar>());
        }
        if (s[0] > 0)
        {
            rows.append(FixedList<scalar, 4>({s[1]/s[0], s[2]/s[0], s[3]/s[0], s[4]/s[0]}));
        }
    }
    return rows;
}


//- The profile of the bins' rows: the axis' row first (a + b r^2 through
//  the two innermost bins; k and nu_t at least 0), the no-slip wall's at
//  radius R last
Foam::List<Foam::FixedList<Foam::scalar, 4>> profileRows
(
    const Foam::List<Foam::FixedList<Foam::scalar, 4>>& bins,
    const Foam::scalar R
)
{
    using namespace Foam;
    FixedList<scalar, 4> axis;
    axis[0] = 0;
    const scalar r1 = sqr(bins[0][0]), r2 = sqr(bins[1][0]);
    for (label j = 1; j < 4; ++j)
    {
        axis[j] = (r2*bins[0][j] - r1*bins[1][j])/(r2 - r1);
    }
    axis[2] = max(axis[2], scalar(0));
    axis[3] = max(axis[3], scalar(0));
    List<FixedList<scalar, 4>> rows(1, axis);
    rows.append(bins);
    rows.append(FixedList<scalar, 4>({R, 0, 0, 0}));
    return rows;
}


//- The rows, one a line: "<indent>(r w k nu_t)" or, without brackets,
//  "<indent>r w k nu_t"
void writeRows
(
    Foam::Ostream& os,
    const Foam::List<Foam::FixedList<Foam::scalar, 4>>& rows,
    const bool brackets
)
{
    for (const Foam::FixedList<Foam::scalar, 4>& row : rows)
    {
        os  << "    " << (brackets ? "(" : "") << row[0] << ' ' << row[1] << ' '
            << row[2] << ' ' << row[3] << (brackets ? ")" : "") << Foam::nl;
    }
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "The mean flow of a computed riser carrier as a radial profile"
        " (constant/riserCarrierProfile, for 'profile tabulated')"
    );
    timeSelector::addOptions(true, false);
    argList::addOption("bins", "n", "number of bins across the radius (default 10)");

    #include "setRootCase.H"
    #include "createTime.H"

    const instantList times = timeSelector::selectIfPresent(runTime, args);
    if (times.empty())
    {
        FatalErrorInFunction << "no time selected" << exit(FatalError);
    }
    runTime.setTime(times.last(), times.size() - 1);

    #include "createMesh.H"

    const label nBins = args.getOrDefault<label>("bins", 10);
    if (nBins < 3 || nBins > 1000)
    {
        FatalErrorInFunction
            << "option -bins " << nBins << " is outside [3, 1000]" << exit(FatalError);
    }

    const riser::RiserFlow& flow = riserModel::New(mesh).flow();
    const scalar R = flow.radius();
    const scalar t = runTime.value();
    const List<FixedList<scalar, 4>> bins = binnedMeans(mesh, flow, t, nBins);
    if (bins.size() < 2)
    {
        FatalErrorInFunction
            << "cells in " << bins.size() << " bin(s) only: lower -bins"
            << exit(FatalError);
    }
    const List<FixedList<scalar, 4>> rows = profileRows(bins, R);

    // in the case's constant/ (the undecomposed case's in a parallel run)
    const IOobject io
    (
        "riserCarrierProfile", runTime.constant(), mesh,
        IOobject::NO_READ, IOobject::NO_WRITE, false
    );
    const fileName file(runTime.globalPath()/runTime.constant()/io.name());
    if (Pstream::master())
    {
        OFstream os(file);
        os.precision(12);
        io.writeHeader(os, IOdictionary::typeName);
        os  << "// riserCarrierProfile: the mean flow of " << runTime.globalPath()
            << " at t = " << t << " s, " << bins.size() << " bins of "
            << R/nBins << " m" << nl
            << "// rows: r [m], w [m/s], k [m^2/s^2], nu_t [m^2/s]" << nl << nl
            << "rows" << nl << "(" << nl;
        writeRows(os, rows, true);
        os  << ");" << nl;
    }

    Info<< "riserCarrierProfile: the mean flow at t = " << t << " s in "
        << bins.size() << " bins of " << R/nBins << " m, written to "
        << file << nl << "    r [m]  w [m/s]  k [m^2/s^2]  nu_t [m^2/s]" << nl;
    writeRows(Info, rows, false);
    Info<< nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
