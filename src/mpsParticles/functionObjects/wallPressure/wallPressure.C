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

#include "wallPressure.H"
#include "inputChecks.H"
#include "mpsState.H"
#include "fluidStructureInterface.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "allRanks.H"
#include "writeChecks.H"
#include "Tuple2.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(wallPressure, 0);
    addToRunTimeSelectionTable(functionObject, wallPressure, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::wallPressure::setProbes()
{
    const mpsState& state = mpsState::lookup(mesh_);
    const mpsCloud& cloud = state.cloud();
    const scalar l0 = state.fluid().l0();
    const label r = cloud.regionIndex(regionName_);
    const fluidStructureInterface* coupling =
        mesh_.findObject<fluidStructureInterface>
        (
            fluidStructureInterface::typeName
        );

    // The region's wall particles in the reference state: where the
    // structure they follow puts them there, else where they are
    // (under -parallel those of every rank, in the order of their ids,
    // the serial cloud's)
    List<Tuple2<label, vector2D>> wall;
    {
        DynamicList<Tuple2<label, vector2D>> mine;
        for
        (
            label i = cloud.begin(particleKind::wall);
            i < cloud.end(particleKind::wall);
            ++i
        )
        {
            if (cloud.region()[i] != r || cloud.halo()[i])
            {
                continue;
            }
            vector2D Xi(cloud.x()[i]);
            if (coupling && coupling->active())
            {
                coupling->referencePosition(cloud.id()[i], Xi);
            }
            mine.append(Tuple2<label, vector2D>(cloud.id()[i], Xi));
        }
        wall = allRanksByFirst<Tuple2<label, vector2D>>(mine);
    }
    labelList ids(wall.size());
    List<vector2D> X(wall.size());
    forAll(wall, j)
    {
        ids[j] = wall[j].first();
        X[j] = wall[j].second();
    }

    const label nProbes = probeNames_.size();
    idA_.setSize(nProbes);
    idB_.setSize(nProbes);
    weightB_.setSize(nProbes);
    position0_.setSize(nProbes);
    samples_.setSize(nProbes);
    sums_.setSize(nProbes, Zero);

    forAll(probeNames_, pi)
    {
        const dictionary& d = probesDict_.subDict(probeNames_[pi]);
        const vector2D end(d.get<vector2D>("end"));
        vector2D t(d.get<vector2D>("direction"));
        const scalar distance = d.get<scalar>("distance");
        if (mag(t) < SMALL)
        {
            FatalIOErrorInFunction(d)
                << "Entry 'direction' of transducer " << probeNames_[pi]
                << " is zero: give the direction along the wall"
                << exit(FatalIOError);
        }
        t /= mag(t);
        const vector2D nrm(-t.y(), t.x());

        // The wall layer nearest the line end + s t, for s from -l0 on
        scalar nearest = GREAT;
        forAll(X, j)
        {
            const vector2D d0(X[j] - end);
            if ((d0 & t) >= -l0)
            {
                nearest = min(nearest, mag(d0 & nrm));
            }
        }
        // ... and its two particles that straddle the distance
        label a = -1, b = -1;
        scalar sa = -GREAT, sb = GREAT;
        forAll(X, j)
        {
            const vector2D d0(X[j] - end);
            const scalar sj = d0 & t;
            if (sj < -l0 || mag(d0 & nrm) > nearest + 0.5*l0)
            {
                continue;
            }
            if (sj <= distance && sj > sa)
            {
                sa = sj;
                a = j;
            }
            if (sj > distance && sj < sb)
            {
                sb = sj;
                b = j;
            }
        }
        if (a < 0 || b < 0 || sb - sa > 1.5*l0)
        {
            FatalIOErrorInFunction(d)
                << "Transducer " << probeNames_[pi] << ": no two wall"
                << " particles of region " << regionName_ << " straddle the"
                << " distance " << distance << " m from " << end
                << " along " << t << " (the wall layer runs from "
                << max(scalar(-l0), min(sa, sb)) << " to "
                << max(sa, sb == GREAT ? sa : sb) << " m there)" << nl
                << "Give a point at the end of the wall region and a"
                << " distance along it" << exit(FatalIOError);
        }
        idA_[pi] = ids[a];
        idB_[pi] = ids[b];
        weightB_[pi] = (distance - sa)/(sb - sa);
        position0_[pi] = (1 - weightB_[pi])*X[a] + weightB_[pi]*X[b];
    }
}


Foam::scalar Foam::functionObjects::wallPressure::pressure
(
    const mpsState& state,
    const label i
) const
{
    return
        fluidPressure_
      ? max(scalar(0), state.fluid().fluidPressureAt(i))
      : state.cloud().p()[i];
}


void Foam::functionObjects::wallPressure::writeSnapshot() const
{
    const mpsState& state = mpsState::lookup(mesh_);
    const mpsCloud& cloud = state.cloud();
    const scalar q = 0.5*state.fluid().rho()*sqr(Uref_);
    const label r = cloud.regionIndex(regionName_);

    // The region's wall particles (under -parallel gathered from every
    // rank, in the order of their ids: the serial cloud's)
    DynamicList<Tuple2<label, vector>> mine;
    for
    (
        label i = cloud.begin(particleKind::wall);
        i < cloud.end(particleKind::wall);
        ++i
    )
    {
        if (cloud.region()[i] == r && !cloud.halo()[i])
        {
            const vector2D& x = cloud.x()[i];
            mine.append
            (
                Tuple2<label, vector>
                (
                    cloud.id()[i],
                    vector(x.x(), x.y(), pressure(state, i))
                )
            );
        }
    }
    const List<Tuple2<label, vector>> wall
    (
        allRanksByFirst<Tuple2<label, vector>>(mine)
    );
    if (!Pstream::master())
    {
        return;
    }

    // Written under a temporary name and renamed when complete
    const fileName dir(baseTimeDir());
    mkDir(dir);
    const fileName path(dir/"wallPressure.dat");
    const fileName failed
    (
        writeChecks::writes
        (
            [&]()
            {
                OFstream os(path + ".tmp");
                os.precision(writePrecision_);
                writeHeader
                (
                    os,
                    "Pressure of the wall particles of region " + regionName_
                );
                writeHeaderValue(os, "rho [kg/m3]", state.fluid().rho());
                writeHeaderValue(os, "Uref [m/s]", Uref_);
                writeHeaderValue(os, "pRef [Pa]", pRef_);
                writeHeaderValue(os, "pressure", word(fluidPressure_ ? "fluid" : "solved"));
                writeCommented(os, "x");
                writeTabbed(os, "y");
                writeTabbed(os, "p");
                writeTabbed(os, "Cp");
                os  << nl;
                for (const Tuple2<label, vector>& w : wall)
                {
                    const vector& v = w.second();
                    os  << v.x() << tab << v.y() << tab << v.z() << tab
                        << (v.z() - pRef_)/q << nl;
                }
                return writeChecks::flushed(os) ? fileName() : path;
            }
        )
    );
    if (!failed.empty())
    {
        Foam::rm(path + ".tmp");
        writeChecks::stopSeries(path, time_);
    }
    Foam::mv(path + ".tmp", path);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::wallPressure::wallPressure
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name),
    Uref_(0),
    pRef_(0),
    fluidPressure_(false),
    filterWidth_(0)
{
    read(dict);

    // The region is checked now, when the particles are there: a wrong
    // name stops the run before anything is written
    const mpsState* state = mesh_.findObject<mpsState>(mpsState::typeName);
    if (state)
    {
        const wordList valid
        (
            state->cloud().regionNames({particleKind::wall})
        );
        if (!valid.found(regionName_))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'wall': " << regionName_ << " is not a region of"
                << " wall particles in system/particleDict" << nl
                << "Valid wall regions: " << valid << exit(FatalIOError);
        }
        setProbes();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::wallPressure::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    inputChecks::keywords
    (
        dict,
        inputChecks::functionObjectKeywords
        (
            {"wall", "Uref", "pRef", "pressure", "probes", "filterWidth"}
        ),
        "function object " + name()
    );
    writeFile::read(dict);
    regionName_ = dict.get<word>("wall");
    Uref_ = dict.get<scalar>("Uref");
    if (!(Uref_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'Uref' (reference speed [m/s]) must be positive, got "
            << Uref_ << exit(FatalIOError);
    }
    pRef_ = dict.getOrDefault<scalar>("pRef", 0);
    const word which(dict.getOrDefault<word>("pressure", "solved"));
    if (which != "solved" && which != "fluid")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'pressure': " << which << " is not valid" << nl
            << "Valid pressures: (solved fluid)" << exit(FatalIOError);
    }
    fluidPressure_ = (which == "fluid");

    const dictionary* probes = inputChecks::optionalDict(dict, "probes");
    probesDict_ = probes ? *probes : dictionary();
    probeNames_ = probesDict_.toc();
    for (const word& probe : probeNames_)
    {
        if (!probesDict_.isDict(probe))
        {
            FatalIOErrorInFunction(probesDict_)
                << "Entry 'probes': " << probe << " must be a dictionary"
                << " { end (x y); direction (dx dy); distance d; }"
                << exit(FatalIOError);
        }
        const dictionary& d = probesDict_.subDict(probe);
        inputChecks::keywords
        (
            d,
            {"end", "direction", "distance"},
            "transducer " + probe + " of function object " + name()
        );
        for (const word key : {"end", "direction", "distance"})
        {
            if (!d.found(key))
            {
                FatalIOErrorInFunction(d)
                    << "Transducer " << probe << ": entry '" << key
                    << "' missing (entries: end (x y), direction (dx dy),"
                    << " distance [m])" << exit(FatalIOError);
            }
        }
    }
    filterWidth_ = dict.getOrDefault<scalar>("filterWidth", 0);
    if (filterWidth_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'filterWidth' (width of the running mean [s]) must"
            << " not be negative, got " << filterWidth_
            << exit(FatalIOError);
    }
    return true;
}


bool Foam::functionObjects::wallPressure::execute()
{
    if (probeNames_.empty())
    {
        return true;
    }
    const mpsState& state = mpsState::lookup(mesh_);
    const mpsCloud& cloud = state.cloud();
    const scalar t = time_.value();

    // Each particle's pressure from the rank that owns it
    auto ownedPressure = [&](const label id)
    {
        const label i = cloud.index(id);
        return (i >= 0 && !cloud.halo()[i]) ? pressure(state, i) : 0;
    };
    scalarList pa(probeNames_.size()), pb(probeNames_.size());
    forAll(probeNames_, pi)
    {
        pa[pi] = ownedPressure(idA_[pi]);
        pb[pi] = ownedPressure(idB_[pi]);
    }
    combineRanks(pa, plusEqOp<scalar>());
    combineRanks(pb, plusEqOp<scalar>());
    forAll(probeNames_, pi)
    {
        const scalar p = (1 - weightB_[pi])*pa[pi] + weightB_[pi]*pb[pi];

        // Running mean over (t - W, t]: the newest sample in, those that
        // have left the window out (without a filter, the sample alone).
        // Times that are W apart in exact arithmetic count as W apart
        // (the time's round-off is far below 1e-9 W)
        std::deque<std::pair<scalar, scalar>>& q = samples_[pi];
        q.emplace_back(t, p);
        sums_[pi] += p;
        const scalar start = t - filterWidth_*(1 - 1e-9);
        while (q.size() > 1 && !(q.front().first > start))
        {
            sums_[pi] -= q.front().second;
            q.pop_front();
        }
    }
    return true;
}


bool Foam::functionObjects::wallPressure::write()
{
    if (time_.writeTime() || !probeNames_.size())
    {
        writeSnapshot();
    }
    if (probeNames_.empty() || !Pstream::master())
    {
        return true;
    }

    if (!probeFile_)
    {
        probeFile_ = createFile("p");
        OFstream& os = probeFile_();
        writeHeader
        (
            os,
            "Transducers on the wall region " + regionName_ + ": p [Pa]"
        );
        if (filterWidth_ > 0)
        {
            writeHeaderValue
            (
                os,
                "filter",
                "causal running mean over the time steps in (t - W, t],"
                " W = " + Foam::name(filterWidth_) + " s (lags by W/2)"
            );
        }
        else
        {
            writeHeaderValue(os, "filter", word("none"));
        }
        forAll(probeNames_, pi)
        {
            writeCommented(os, "Probe " + Foam::name(pi));
            os  << ' ' << vector(position0_[pi].x(), position0_[pi].y(), 0)
                << ' ' << probeNames_[pi] << nl;
        }
        writeCommented(os, "Time");
        for (const word& probe : probeNames_)
        {
            writeTabbed(os, probe);
        }
        os  << endl;
    }

    const fileName failed
    (
        writeChecks::writes
        (
            [this]()
            {
                OFstream& os = probeFile_();
                writeCurrentTime(os);
                forAll(probeNames_, pi)
                {
                    os  << tab
                        << sums_[pi]/max(label(1), label(samples_[pi].size()));
                }
                os  << endl;
                return writeChecks::flushed(os) ? fileName() : os.name();
            }
        )
    );
    if (!failed.empty())
    {
        writeChecks::stopSeries(failed, time_);
    }
    return true;
}


// ************************************************************************* //
