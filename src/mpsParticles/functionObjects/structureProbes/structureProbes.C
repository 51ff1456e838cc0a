/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | mpsFsiFoam: MPS hydroelastic slamming
   \\    /   O peration     | built on OpenFOAM v1912
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of mpsFsiFoam, distributed under the GNU General Public
    License version 3 or later, as OpenFOAM is.

\*---------------------------------------------------------------------------*/

#include "structureProbes.H"
#include "inputChecks.H"
#include "mpsStructure.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(structureProbes, 0);
    addToRunTimeSelectionTable(functionObject, structureProbes, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::structureProbes::writeFileHeader(OFstream& os)
{
    writeHeader(os, "Structure probes: displacement [m]");
    forAll(points_, i)
    {
        writeCommented(os, "Probe " + Foam::name(i));
        os  << ' ' << vector(points_[i].x(), points_[i].y(), 0)
            << "  " << names_[i] << nl;
    }
    writeCommented(os, "Time");
    for (const word& n : names_)
    {
        writeTabbed(os, n + "_x");
        writeTabbed(os, n + "_y");
    }
    os  << endl;
}


void Foam::functionObjects::structureProbes::locate
(
    const structureModel& s
)
{
    const List<vector2D>& X = s.X();
    carriers_.setSize(points_.size());
    forAll(points_, i)
    {
        scalar dMin = GREAT;
        forAll(X, k)
        {
            dMin = min(dMin, mag(X[k] - points_[i]));
        }
        // A reference point on the structure: within a spacing of a
        // particle (one farther off would follow an arbitrary one)
        if (dMin > s.spacing())
        {
            FatalErrorInFunction
                << "Function object " << name() << ": probe " << names_[i]
                << " at " << points_[i]
                << " is " << dMin << " m from the nearest structural"
                << " particle (more than the spacing " << s.spacing()
                << " m): give a point on the structure"
                << exit(FatalError);
        }
        DynamicList<label> c;
        forAll(X, k)
        {
            if (mag(X[k] - points_[i]) <= dMin*(1 + 1e-6) + 1e-12)
            {
                c.append(k);
            }
        }
        carriers_[i] = std::move(c);
    }
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::structureProbes::structureProbes
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeSeriesFile(name, runTime, dict, "displacement")
{
    read(dict);

    // Locate the probes now when the structure is there: one off the
    // structure stops the run before anything is written
    const mpsStructure* structure =
        mesh_.findObject<mpsStructure>(mpsStructure::typeName);
    if (inSolver())
    {
        // In the solver: a case without structure stops here
        mpsStructure::lookup(mesh_);
    }
    if (structure && structure->active())
    {
        locate(structure->model());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::structureProbes::read(const dictionary& dict)
{
    readEntries(dict, {"probes"});

    const dictionary& probes = inputChecks::subDict(dict, "probes");
    names_ = probes.toc();
    points_.setSize(names_.size());
    forAll(names_, i)
    {
        points_[i] = probes.get<vector2D>(names_[i]);
    }
    if (names_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "No probes in 'probes' (name (x y) pairs)"
            << exit(FatalIOError);
    }
    carriers_.clear();
    return true;
}


void Foam::functionObjects::structureProbes::update()
{
    if (carriers_.empty())
    {
        locate(mpsStructure::lookup(mesh_).model());
    }
}


void Foam::functionObjects::structureProbes::writeValues(OFstream& os)
{
    const structureModel& s = mpsStructure::lookup(mesh_).model();
    const List<vector2D>& X = s.X();
    forAll(points_, i)
    {
        vector2D u(Zero);
        for (const label k : carriers_[i])
        {
            const vector2D r(points_[i] - X[k]);
            u +=
                s.displacement(k)
              + structureModel::rotate(s.theta()[k], r) - r;
        }
        u /= carriers_[i].size();
        os  << tab << u.x() << tab << u.y();
    }
}


// ************************************************************************* //
