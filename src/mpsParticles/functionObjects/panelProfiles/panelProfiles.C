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

#include "panelProfiles.H"
#include "inputChecks.H"
#include "mpsState.H"
#include "mpsStructure.H"
#include "writeChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(panelProfiles, 0);
    addToRunTimeSelectionTable(functionObject, panelProfiles, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::panelProfiles::locate()
{
    const mpsStructure& structure = mpsStructure::lookup(mesh_);
    const structureModel& s = structure.model();
    const List<vector2D>& X = s.X();
    const List<bool>& clamped = s.clamped();
    const scalar ds = s.spacing();

    for (panel& p : panels_)
    {
        const labelList particles(structure.regionParticles(p.region, p.dict));
        p.axis = structure.geometry().axis(particles, p.end);
        const labelList face
        (
            structure.geometry().surfaceLayer(particles, p.normal)
        );
        if (face.empty())
        {
            FatalIOErrorInFunction(p.dict)
                << "Panel " << p.name << ": region " << p.region
                << " has no particles on the face with outward normal "
                << p.normal << exit(FatalIOError);
        }

        // The face's reach from the end
        scalar sFirst = GREAT, sLast = -GREAT;
        label first = face.first();
        for (const label k : face)
        {
            const scalar sk = (X[k] - p.end) & p.axis;
            if (sk < sFirst)
            {
                sFirst = sk;
                first = k;
            }
            sLast = max(sLast, sk);
        }

        // The stations: multiples of spacing within that reach, each
        // between two face particles as a strainProbes gauge
        DynamicList<station> stations;
        for (label m = 1; m*spacing_ < sLast; ++m)
        {
            station st;
            st.distance = m*spacing_;
            if (st.distance < sFirst)
            {
                continue;
            }
            if
            (
                !structure.geometry().straddle
                (
                    face, p.end, p.axis, st.distance, st.a, st.b, st.weight
                )
            )
            {
                FatalIOErrorInFunction(p.dict)
                    << "Panel " << p.name << ": the face of region "
                    << p.region << " has a gap of more than two spacings at "
                    << st.distance << " m from " << p.end << ": not a panel"
                    << exit(FatalIOError);
            }
            st.location =
                (1 - st.weight)*X[st.a] + st.weight*X[st.b]
              + (0.5*ds)*p.normal;
            stations.append(st);
        }
        if (stations.empty())
        {
            FatalIOErrorInFunction(p.dict)
                << "Panel " << p.name << ": no station at a multiple of "
                << spacing_ << " m within the face of region " << p.region
                << " (" << sFirst << " to " << sLast << " m from "
                << p.end << "): a smaller spacing" << exit(FatalIOError);
        }
        p.stations.transfer(stations);

        // The reference of the deflection: the clamped particle nearest
        // the end (the body), else the face's particle nearest it
        p.origin = first;
        scalar nearest = GREAT;
        forAll(clamped, i)
        {
            if (clamped[i] && magSqr(X[i] - p.end) < nearest)
            {
                nearest = magSqr(X[i] - p.end);
                p.origin = i;
            }
        }
    }
    located_ = true;
}


void Foam::functionObjects::panelProfiles::writeFileHeader
(
    OFstream& os,
    const panel& p,
    const word& quantity
) const
{
    writeHeader
    (
        os,
        quantity == "strain"
      ? "Panel " + p.name + ": axial strain along region " + p.region
      + " at its face, tension positive"
      : "Panel " + p.name + ": deflection of region " + p.region
      + " [m], against the face's outward normal, relative to particle "
      + Foam::name(p.origin)
    );
    writeCommented
    (
        os,
        "End " + Foam::name(p.end.x()) + " " + Foam::name(p.end.y())
      + ", face normal " + Foam::name(p.normal.x()) + " "
      + Foam::name(p.normal.y()) + ", axis " + Foam::name(p.axis.x()) + " "
      + Foam::name(p.axis.y())
    );
    os  << nl;
    forAll(p.stations, k)
    {
        const station& st = p.stations[k];
        writeCommented(os, "Station " + Foam::name(k));
        os  << " s " << st.distance << ' '
            << vector(st.location.x(), st.location.y(), 0) << nl;
    }
    writeCommented(os, "Time");
    for (const station& st : p.stations)
    {
        writeTabbed(os, "s" + Foam::name(std::round(1e4*st.distance)/10));
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::panelProfiles::panelProfiles
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    logFiles(mesh_, name),
    spacing_(0),
    located_(false),
    headerWritten_(false)
{
    read(dict);

    // Locate the stations now when the structure is there: a panel that
    // is none stops the run before any file is opened
    const mpsStructure* structure =
        mesh_.findObject<mpsStructure>(mpsStructure::typeName);
    if (mesh_.foundObject<mpsState>(mpsState::typeName))
    {
        mpsStructure::lookup(mesh_);
    }
    if (structure && structure->active())
    {
        locate();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::panelProfiles::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    inputChecks::keywords
    (
        dict,
        inputChecks::functionObjectKeywords({"spacing", "panels"}),
        "function object " + name()
    );
    logFiles::read(dict);

    spacing_ = dict.get<scalar>("spacing");
    if (!(spacing_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'spacing' (the distance between stations along a"
            << " panel [m]) must be positive, got " << spacing_
            << exit(FatalIOError);
    }

    const dictionary& panelsDict = inputChecks::subDict(dict, "panels");
    panels_.setSize(panelsDict.size());
    label i = 0;
    for (const entry& e : panelsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(panelsDict)
                << "Panel " << e.keyword() << " must be a dictionary"
                << " (region, end, surface)" << exit(FatalIOError);
        }
        panel& p = panels_[i++];
        p.name = e.keyword();
        p.dict = e.dict();
        inputChecks::keywords
        (
            p.dict,
            {"region", "end", "surface"},
            "panel " + p.name
        );
        p.region = p.dict.get<word>("region");
        p.end = p.dict.get<vector2D>("end");
        p.normal = p.dict.get<vector2D>("surface");
        if (mag(p.normal) < SMALL)
        {
            FatalIOErrorInFunction(p.dict)
                << "Entry 'surface' (outward normal of the face) of panel "
                << p.name << " must not be zero" << exit(FatalIOError);
        }
        p.normal /= mag(p.normal);
    }
    if (panels_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "No panels in 'panels'" << exit(FatalIOError);
    }
    located_ = false;
    return true;
}


bool Foam::functionObjects::panelProfiles::write()
{
    if (!located_)
    {
        locate();
    }
    if (!headerWritten_)
    {
        wordList names(2*panels_.size());
        forAll(panels_, i)
        {
            names[2*i] = panels_[i].name + "_strain";
            names[2*i + 1] = panels_[i].name + "_deflection";
        }
        resetNames(names);
    }
    if (Pstream::master())
    {
        const structureModel& s = mpsStructure::lookup(mesh_).model();
        const List<vector2D>& X = s.X();
        const List<vector2D>& x = s.x();
        const scalar dn = 0.5*s.spacing();

        const fileName failed
        (
            writeChecks::writes
            (
                [&]()
                {
                    forAll(panels_, i)
                    {
                        const panel& p = panels_[i];
                        const vector2D u0(x[p.origin] - X[p.origin]);
                        for (const label q : {0, 1})
                        {
                            OFstream& os = files(2*i + q);
                            if (!headerWritten_)
                            {
                                writeFileHeader
                                (
                                    os, p, q ? "deflection" : "strain"
                                );
                            }
                            writeCurrentTime(os);
                            for (const station& st : p.stations)
                            {
                                scalar va, vb;
                                if (q == 0)
                                {
                                    va = s.axialStrain(st.a, p.axis, p.normal, dn);
                                    vb = s.axialStrain(st.b, p.axis, p.normal, dn);
                                }
                                else
                                {
                                    va = -((x[st.a] - X[st.a] - u0) & p.normal);
                                    vb = -((x[st.b] - X[st.b] - u0) & p.normal);
                                }
                                os  << tab
                                    << (1 - st.weight)*va + st.weight*vb;
                            }
                            os  << endl;
                            if (!writeChecks::flushed(os))
                            {
                                return fileName(os.name());
                            }
                        }
                    }
                    return fileName();
                }
            )
        );
        if (!failed.empty())
        {
            writeChecks::stopSeries(failed, time_);
        }
    }
    headerWritten_ = true;
    return true;
}


// ************************************************************************* //
