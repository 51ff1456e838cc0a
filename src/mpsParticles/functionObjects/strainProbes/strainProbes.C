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

#include "strainProbes.H"
#include "inputChecks.H"
#include "mpsStructure.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(strainProbes, 0);
    addToRunTimeSelectionTable(functionObject, strainProbes, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::strainProbes::locate()
{
    const mpsStructure& structure = mpsStructure::lookup(mesh_);
    const structureModel& s = structure.model();
    const List<vector2D>& X = s.X();
    const scalar ds = s.spacing();

    for (gauge& g : gauges_)
    {
        const labelList panel(structure.regionParticles(g.region, g.dict));
        g.axis = structure.geometry().axis(panel, g.end);
        const labelList face
        (
            structure.geometry().surfaceLayer(panel, g.normal)
        );

        if (face.empty())
        {
            FatalIOErrorInFunction(g.dict)
                << "Gauge " << g.name << ": region " << g.region
                << " has no particles on the face with outward normal "
                << g.normal << exit(FatalIOError);
        }
        if
        (
            !structure.geometry().straddle
            (
                face, g.end, g.axis, g.distance, g.a, g.b, g.weight
            )
        )
        {
            FatalIOErrorInFunction(g.dict)
                << "Gauge " << g.name << " at " << g.distance
                << " m from " << g.end << " lies off the panel "
                << g.region << " (or across a gap in its face)"
                << exit(FatalIOError);
        }
        g.location =
            (1 - g.weight)*X[g.a] + g.weight*X[g.b] + (0.5*ds)*g.normal;
    }
    located_ = true;
}


void Foam::functionObjects::strainProbes::writeFileHeader(OFstream& os)
{
    writeHeader(os, "Strain gauges: axial strain along the panel at its face,"
        " tension positive");
    forAll(gauges_, i)
    {
        const gauge& g = gauges_[i];
        writeCommented(os, "Probe " + Foam::name(i));
        os  << ' ' << vector(g.location.x(), g.location.y(), 0) << "  "
            << g.name << ": region " << g.region << ", " << g.distance
            << " m from " << g.end << ", face " << g.normal << nl;
    }
    writeCommented(os, "Time");
    for (const gauge& g : gauges_)
    {
        writeTabbed(os, g.name);
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::strainProbes::strainProbes
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeSeriesFile(name, runTime, dict, "strain"),
    located_(false)
{
    read(dict);

    // Locate the gauges now when the structure is there: a gauge off its
    // panel stops the run before any file is opened
    const mpsStructure* structure =
        mesh_.findObject<mpsStructure>(mpsStructure::typeName);
    if (inSolver())
    {
        // In the solver: a case without structure stops here
        mpsStructure::lookup(mesh_);
    }
    if (structure && structure->active())
    {
        locate();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::strainProbes::read(const dictionary& dict)
{
    readEntries(dict, {"gauges"});

    const dictionary& gaugesDict = inputChecks::subDict(dict, "gauges");
    gauges_.setSize(gaugesDict.size());
    label i = 0;
    for (const entry& e : gaugesDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(gaugesDict)
                << "Gauge " << e.keyword() << " must be a dictionary"
                << " (region, end, distance, surface)"
                << exit(FatalIOError);
        }
        gauge& g = gauges_[i++];
        g.name = e.keyword();
        g.dict = e.dict();
        inputChecks::keywords
        (
            g.dict,
            {"region", "end", "distance", "surface"},
            "gauge " + g.name
        );
        g.region = g.dict.get<word>("region");
        g.end = g.dict.get<vector2D>("end");
        g.distance = g.dict.get<scalar>("distance");
        g.normal = g.dict.get<vector2D>("surface");
        if (mag(g.normal) < SMALL)
        {
            FatalIOErrorInFunction(g.dict)
                << "Entry 'surface' (outward normal of the face) of gauge "
                << g.name << " must not be zero" << exit(FatalIOError);
        }
        g.normal /= mag(g.normal);
    }
    if (gauges_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "No gauges in 'gauges'" << exit(FatalIOError);
    }
    located_ = false;
    return true;
}


void Foam::functionObjects::strainProbes::update()
{
    if (!located_)
    {
        locate();
    }
}


void Foam::functionObjects::strainProbes::writeValues(OFstream& os)
{
    const structureModel& s = mpsStructure::lookup(mesh_).model();
    const scalar dn = 0.5*s.spacing();
    for (const gauge& g : gauges_)
    {
        const scalar ea = s.axialStrain(g.a, g.axis, g.normal, dn);
        const scalar eb = s.axialStrain(g.b, g.axis, g.normal, dn);
        os  << tab << (1 - g.weight)*ea + g.weight*eb;
    }
}


// ************************************************************************* //
