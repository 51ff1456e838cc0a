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

#include "mpsStructure.H"
#include "lookupRegistered.H"
#include "lagrangianCloudReader.H"
#include "inputChecks.H"
#include "Time.H"
#include "clockValue.H"
#include "IOField.H"
#include "allRanks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(mpsStructure, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<bool> Foam::mpsStructure::readClamped() const
{
    List<bool> clamped(ids_.size(), false);
    const wordList names
    (
        dict_.getOrDefault<wordList>("clamped", wordList())
    );
    for (const word& name : names)
    {
        const label r = regionIndex(name, dict_);
        forAll(region_, k)
        {
            clamped[k] = clamped[k] || region_[k] == r;
        }
    }
    return clamped;
}


void Foam::mpsStructure::readBodyMotion(const scalar startTime)
{
    if (!dict_.found("bodyMotion"))
    {
        return;
    }
    if
    (
        dict_.found("clampedVelocity")
     || dict_.getOrDefault<wordList>("clamped", wordList()).empty()
    )
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'bodyMotion' moves the clamped regions: it needs"
            << " an entry 'clamped' (the regions it moves) and no entry"
            << " 'clampedVelocity'" << exit(FatalIOError);
    }
    motion_ = bodyMotion::New(dict_, startTime);
    model_->setClampedVelocity(motion_->velocity());

    // The body moves as a whole at the start (the wedge dropped onto the
    // water), unless initialVelocity says otherwise
    model_->v() = motion_->velocity();
}


void Foam::mpsStructure::setInitialVelocity(const dictionary& dict)
{
    const labelList particles
    (
        regionParticles(dict.get<word>("region"), dict)
    );
    const vector2D origin(dict.get<vector2D>("origin"));
    vector2D a(dict.get<vector2D>("axis"));
    if (mag(a) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'axis' must not be zero" << exit(FatalIOError);
    }
    a /= mag(a);
    const vector2D n(-a.y(), a.x());
    autoPtr<Function1<vector>> profile
    (
        Function1<vector>::New("velocity", dict)
    );
    const scalar h = 1e-3*model_->spacing();
    for (const label k : particles)
    {
        if (model_->clamped()[k])
        {
            continue;
        }
        const scalar sk = (model_->X()[k] - origin) & a;
        const vector v(profile->value(sk));
        model_->v()[k] = vector2D(v.x(), v.y());
        const vector vp(profile->value(sk + h)), vm(profile->value(sk - h));
        model_->omega()[k] =
            ((vector2D(vp.x(), vp.y()) - vector2D(vm.x(), vm.y())) & n)/(2*h);
    }
    Info<< "Structure initial velocity on " << particles.size()
        << " particles of region " << dict.get<word>("region") << endl;
}


void Foam::mpsStructure::readLoads(const dictionary& loadsDict)
{
    for (const entry& e : loadsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(loadsDict)
                << "Entry " << e.keyword() << " of loads must be a"
                << " dictionary (region, normal, pressure)"
                << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        inputChecks::keywords
        (
            d,
            {
                "region", "normal", "pressure", "pressureCoeffs",
                "pressureTable", "origin", "direction"
            },
            "load " + e.keyword()
        );
        if (d.found("pressure") == d.found("pressureTable"))
        {
            FatalIOErrorInFunction(d)
                << "Load " << e.keyword() << " needs one of 'pressure' (a"
                << " Function1 of time) and 'pressureTable' (a file of p"
                << " over the distance along the face and time, with"
                << " 'origin' and 'direction')" << exit(FatalIOError);
        }
        surfaceLoad* load = new surfaceLoad;
        load->name = e.keyword();
        load->normal = d.get<vector2D>("normal");
        if (mag(load->normal) < SMALL)
        {
            FatalIOErrorInFunction(d)
                << "Entry 'normal' of load " << e.keyword()
                << " must not be zero" << exit(FatalIOError);
        }
        load->normal /= mag(load->normal);
        load->particles = geometry_->surfaceLayer
        (
            regionParticles(d.get<word>("region"), d),
            load->normal
        );
        if (d.found("pressure"))
        {
            load->pressure = Function1<scalar>::New("pressure", d);
        }
        else
        {
            fileName file(d.get<fileName>("pressureTable"));
            file.expand();
            if (!file.isAbsolute())
            {
                file = time().path()/file;
            }
            load->table.reset(new spaceTimeTable(file, d));
            const vector2D origin(d.get<vector2D>("origin"));
            vector2D dir(d.get<vector2D>("direction"));
            if (mag(dir) < SMALL)
            {
                FatalIOErrorInFunction(d)
                    << "Entry 'direction' of load " << e.keyword()
                    << " must not be zero" << exit(FatalIOError);
            }
            dir /= mag(dir);
            // Each particle's s at its reference position
            const List<vector2D>& X = model_->X();
            load->s.setSize(load->particles.size());
            forAll(load->particles, i)
            {
                load->s[i] = (X[load->particles[i]] - origin) & dir;
            }
        }
        Info<< "Structure load " << load->name << ": pressure on "
            << load->particles.size() << " particles of region "
            << d.get<word>("region") << " facing " << load->normal
            << endl;
        loads_.append(load);
    }
}


Foam::label Foam::mpsStructure::regionIndex
(
    const word& name,
    const dictionary& dict
) const
{
    const wordList valid(cloud_.regionNames({particleKind::structure}));
    if (!valid.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Unknown structure region " << name << " in " << dict.name()
            << nl << "Valid structure regions of system/particleDict: "
            << valid << exit(FatalIOError);
    }
    return cloud_.regionIndex(name);
}


void Foam::mpsStructure::checkFinite(const scalar t) const
{
    const label step = db().time().timeIndex();
    forAll(model_->x(), k)
    {
        const vector2D& x = model_->x()[k];
        const bool finite = std::isfinite(x.x()) && std::isfinite(x.y());
        if
        (
            !finite
         || x.x() < domain_.min().x() || x.x() > domain_.max().x()
         || x.y() < domain_.min().y() || x.y() > domain_.max().y()
        )
        {
            FatalErrorInFunction
                << "The structure diverged in the fluid step ending at"
                << " time " << t << " (step " << step << "): particle " << k
                << " (reference " << model_->X()[k] << ") is "
                << (finite ? "outside the domain" : "not finite");
            if (finite)
            {
                FatalError
                    << ", at " << x << " (the background mesh spans "
                    << domain_.min() << " to " << domain_.max() << ")";
            }
            FatalError
                << ". Nothing of this step was written; the last written"
                << " time is intact. Is a load too large, or the structural"
                << " step too long?" << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::mpsStructure::spacing
(
    const dictionary& dict,
    const scalar l0
)
{
    inputChecks::keywords
    (
        dict,
        {
            "structureModel", "rho", "E", "nu", "planeStrain", "spacing",
            "spacingRatio", "nSubSteps", "deltaT", "damping",
            "stiffnessDamping", "g", "clamped", "clampAt",
            "timeIntegration", "clampedVelocity", "bodyMotion",
            "initialVelocity", "loads", "coupling", "releaseTime"
        },
        "constant/structureProperties"
    );
    inputChecks::values
    (
        dict,
        {
            "rho", "E", "nu", "planeStrain", "spacing", "spacingRatio",
            "nSubSteps", "deltaT", "damping", "stiffnessDamping", "g",
            "clamped", "clampAt", "clampedVelocity"
        }
    );
    inputChecks::exclusive(dict, {"spacing", "spacingRatio"});
    inputChecks::exclusive(dict, {"nSubSteps", "deltaT"});
    inputChecks::exclusive(dict, {"clampedVelocity", "bodyMotion"});
    for
    (
        const word& d
      : {"bodyMotion", "initialVelocity", "loads", "coupling", "timeIntegration"}
    )
    {
        inputChecks::optionalDict(dict, d);
    }
    if (const dictionary* iv = dict.findDict("initialVelocity"))
    {
        inputChecks::keywords
        (
            *iv,
            {"region", "origin", "axis", "velocity", "velocityCoeffs"},
            "initialVelocity"
        );
    }

    if (dict.found("spacing"))
    {
        const scalar ds = dict.get<scalar>("spacing");
        if (!(ds > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'spacing' (structural particle spacing [m]) must"
                << " be positive, got " << ds << exit(FatalIOError);
        }
        return ds;
    }
    if (dict.found("spacingRatio"))
    {
        return l0/inputChecks::number<scalar>(dict, "spacingRatio", ">= 1");
    }
    return l0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsStructure::mpsStructure
(
    const objectRegistry& db,
    mpsCloud& cloud,
    const dictionary& structureProperties,
    const scalar fluidDeltaT
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            db.time().constant(),
            db,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            true
        )
    ),
    cloud_(cloud),
    dict_(structureProperties),
    domain_
    (
        isA<polyMesh>(db)
      ? refCast<const polyMesh>(db).bounds()
      : boundBox(point::uniform(-GREAT), point::uniform(GREAT))
    ),
    fluidDeltaT_(-1),
    nSubSteps_(0),
    totalSubSteps_(0),
    wallTime_(0),
    releaseTime_(structureProperties.getOrDefault<scalar>("releaseTime", -GREAT)),
    savedBodyVelocity_(Zero),
    savedSubSteps_(0)
{
    const label begin = cloud_.begin(particleKind::structure);
    const label n = cloud_.count(particleKind::structure);
    if (n == 0)
    {
        return;
    }
    if (!dict_.found("structureModel"))
    {
        FatalIOErrorInFunction(dict_)
            << "The case has " << n << " structure particles:"
            << " constant/structureProperties needs an entry"
            << " structureModel (rotatingParticles, totalLagrangian, rigid)"
            << exit(FatalIOError);
    }

    // The structure's particles in the cloud's order, by id
    ids_ = SubList<label>(cloud_.id(), n, begin);
    List<vector2D> X(SubList<vector2D>(cloud_.x(), n, begin));
    region_ = SubList<label>(cloud_.region(), n, begin);
    forAll(ids_, k)
    {
        modelIndex_.insert(ids_[k], k);
    }
    const scalar ds = cloud_.spacing()[begin + n - 1];

    const List<bool> clamped(readClamped());
    model_ = structureModel::New(dict_, X, clamped, ds);
    geometry_.reset(new structureGeometry(model_->X(), ds));
    model_->setClampedVelocity
    (
        dict_.getOrDefault<vector2D>("clampedVelocity", vector2D::zero)
    );

    readBodyMotion(db.time().value());

    if (dict_.found("initialVelocity"))
    {
        if (dict_.found("releaseTime"))
        {
            FatalIOErrorInFunction(dict_)
                << "Entries 'releaseTime' and 'initialVelocity' exclude each"
                << " other: a held structure is at rest until its release"
                << exit(FatalIOError);
        }
        setInitialVelocity(dict_.subDict("initialVelocity"));
    }
    if (dict_.found("loads"))
    {
        readLoads(dict_.subDict("loads"));
    }

    nSubSteps_ = model_->setSubSteps(fluidDeltaT);
    fluidDeltaT_ = fluidDeltaT;

    Info<< "Structure: " << n << " particles, spacing " << ds << " m, "
        << model_->type() << ", " << findIndices(clamped, true).size()
        << " clamped; step " << model_->deltaT() << " s (" << nSubSteps_
        << " per fluid step), largest stable " << model_->maxStableDeltaT()
        << " s" << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::mpsStructure::beginStep
(
    const scalar t,
    const scalar fluidDeltaT,
    const UList<vector2D>& fluidForce
)
{
    if (!active())
    {
        return false;
    }
    const clockValue clock(true);

    if (mag(fluidDeltaT - fluidDeltaT_) > 1e-12*fluidDeltaT)
    {
        nSubSteps_ = model_->setSubSteps(fluidDeltaT);
        fluidDeltaT_ = fluidDeltaT;
    }

    if (t < releaseTime_ + 0.5*fluidDeltaT)
    {
        // Held until the release: at rest in the reference state
        toCloud();
        wallTime_ += clock.elapsed();
        return false;
    }

    // The body's motion over the step, under the fluid force just solved
    if (motion_.valid())
    {
        vector2D F(Zero);
        for (const vector2D& f : fluidForce)
        {
            F += f;
        }
        motion_->update(t, fluidDeltaT, F);
        model_->setClampedVelocity(motion_->velocity());
    }

    // Fluid forces and loads at the end of the fluid step, held over the
    // sub-steps
    List<vector2D>& f = model_->externalForce();
    if (fluidForce.size())
    {
        f = fluidForce;
    }
    else
    {
        f = Zero;
    }
    const scalar ds = model_->spacing();
    for (const surfaceLoad& load : loads_)
    {
        if (load.table)
        {
            forAll(load.particles, i)
            {
                const scalar p = load.table->value(load.s[i], t);
                f[load.particles[i]] -= (p*ds)*load.normal;
            }
            continue;
        }
        const scalar p = load.pressure->value(t);
        for (const label k : load.particles)
        {
            f[k] -= (p*ds)*load.normal;
        }
    }
    model_->evaluate();
    model_->startSubSteps();
    wallTime_ += clock.elapsed();
    return true;
}


void Foam::mpsStructure::subStep()
{
    const clockValue clock(true);
    model_->subStep();
    ++totalSubSteps_;
    wallTime_ += clock.elapsed();
}


void Foam::mpsStructure::endStep(const scalar t)
{
    const clockValue clock(true);
    checkFinite(t);
    toCloud();
    if (db().time().writeTime())
    {
        // The step after a written time builds its tangent at that state,
        // as a restart from it does: the two continue alike to round-off
        model_->resetTangent();
    }
    wallTime_ += clock.elapsed();
}


void Foam::mpsStructure::saveState()
{
    if (!active())
    {
        return;
    }
    model_->saveState();
    savedBodyVelocity_ =
        motion_.valid() ? motion_->velocity() : vector2D(Zero);
    savedSubSteps_ = totalSubSteps_;
}


void Foam::mpsStructure::restoreState()
{
    if (!active())
    {
        return;
    }
    model_->restoreState();
    if (motion_.valid())
    {
        motion_->restart(savedBodyVelocity_);
    }
    totalSubSteps_ = savedSubSteps_;
    toCloud();
}


void Foam::mpsStructure::toCloud()
{
    if (!active())
    {
        return;
    }
    forAll(ids_, k)
    {
        const label i = cloud_.index(ids_[k]);
        cloud_.x()[i] = model_->x()[k];
        cloud_.U()[i] = model_->v()[k];
    }
}


void Foam::mpsStructure::readRestart(const lagrangianCloudReader& reader)
{
    if (!active())
    {
        return;
    }
    // Under -parallel each rank wrote a part of the structure (that in
    // its cells) and every rank holds all of it: the parts are gathered (a
    // processor without a part has no files when decomposePar wrote them)
    auto io = [&](const word& name)
    {
        IOobject fieldIO(reader.fieldIO("structure", name));
        if (Pstream::parRun())
        {
            fieldIO.readOpt() = IOobject::READ_IF_PRESENT;
        }
        return fieldIO;
    };
    const IOField<label> idIO(io("id"));
    auto read = [&](const word& name, auto zero)
    {
        typedef decltype(zero) Type;
        return allRanks<Type>(IOField<Type>(io(name)));
    };
    const labelList id(allRanks<label>(idIO));
    const List<vector> D(read("D", vector::zero));
    const List<vector> U(read("U", vector::zero));
    const scalarList theta(read("theta", scalar(0)));
    const scalarList omega(read("omega", scalar(0)));

    structureModel& m = model_();
    const word& timeName = idIO.time().timeName();
    if (id.size() != m.size())
    {
        FatalIOErrorInFunction(idIO.objectPath())
            << "The structure written at time " << timeName << " has "
            << id.size() << " particles, the case generates " << m.size()
            << exit(FatalIOError);
    }
    forAll(id, w)
    {
        const auto iter = modelIndex_.cfind(id[w]);
        if (!iter.found())
        {
            FatalIOErrorInFunction(idIO.objectPath())
                << "Structure particle id " << id[w] << " written at time "
                << timeName << " is not generated by system/particleDict"
                << exit(FatalIOError);
        }
        const label k = iter.val();
        m.x()[k] = m.X()[k] + vector2D(D[w].x(), D[w].y());
        m.v()[k] = vector2D(U[w].x(), U[w].y());
        m.theta()[k] = theta[w];
        m.omega()[k] = omega[w];
    }
    // A structure held until releaseTime is written at rest in its
    // reference state: one written moving was released already, and
    // holding it again would stop it dead
    const scalar t = idIO.time().value();
    if (t < releaseTime_ - 1e-9*max(mag(releaseTime_), scalar(1)))
    {
        scalar speed = 0, displacement = 0;
        forAll(D, w)
        {
            speed = max(speed, mag(U[w]) + mag(omega[w]));
            displacement = max(displacement, mag(D[w]) + mag(theta[w]));
        }
        if (speed > 0 || displacement > 0)
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'releaseTime' " << releaseTime_ << " s is after"
                << " the restart time " << timeName << " s, where the"
                << " structure written moves (largest speed " << speed
                << " m/s): it was released already, and holding it until "
                << releaseTime_ << " s would stop it dead. Give releaseTime"
                << " " << timeName << " or earlier, or restart from a time"
                << " before the release" << exit(FatalIOError);
        }
    }
    m.setTime(t);
    m.restored();
    if (m.implicit())
    {
        // The implicit integration's accelerations are part of its state:
        // read where written (a time written by the explicit integration
        // has none, and the first step starts from the equilibrium's)
        bool written = isFile(io("stepAcceleration").objectPath());
        reduce(written, orOp<bool>());
        if (written)
        {
            auto readIfPresent = [&](const word& name, auto zero)
            {
                typedef decltype(zero) Type;
                IOobject fieldIO(reader.fieldIO("structure", name));
                fieldIO.readOpt() = IOobject::READ_IF_PRESENT;
                return allRanks<Type>(IOField<Type>(fieldIO));
            };
            const List<vector> A(readIfPresent("stepAcceleration", vector::zero));
            const scalarList alpha
            (
                readIfPresent("stepAngularAcceleration", scalar(0))
            );
            const List<vector> L(readIfPresent("stepLoad", vector::zero));
            if
            (
                A.size() != id.size() || alpha.size() != id.size()
             || L.size() != id.size()
            )
            {
                FatalIOErrorInFunction(idIO.objectPath())
                    << "The structure written at time " << timeName
                    << " has " << A.size() << " stepAcceleration, "
                    << alpha.size() << " stepAngularAcceleration and "
                    << L.size() << " stepLoad values for " << id.size()
                    << " particles" << exit(FatalIOError);
            }
            List<vector2D> a(m.size(), Zero), load(m.size(), Zero);
            scalarList angular(m.size(), Zero);
            forAll(id, w)
            {
                const label k = modelIndex_[id[w]];
                a[k] = vector2D(A[w].x(), A[w].y());
                angular[k] = alpha[w];
                load[k] = vector2D(L[w].x(), L[w].y());
            }
            m.setStepAccelerations(a, angular, load);
        }
    }
    if (motion_.valid())
    {
        const label k = m.clamped().find(true);
        motion_->restart(m.v()[k]);
        m.setClampedVelocity(motion_->velocity());
    }
    toCloud();
    Info<< "Structure: continuing from the state written at time "
        << timeName << endl;
}


Foam::labelList Foam::mpsStructure::regionParticles
(
    const word& name,
    const dictionary& dict
) const
{
    const label r = regionIndex(name, dict);
    return findIndices(region_, r);
}


void Foam::mpsStructure::addFields
(
    const labelUList& ids,
    fieldTable& table
) const
{
    if (!active())
    {
        return;
    }
    const structureModel& m = model_();
    const label n = ids.size();
    vectorField D(n);
    scalarField theta(n), omega(n), exx(n), eyy(n), exy(n), axial(n);

    // axial strain along the long axis of each region
    Map<vector2D> axes;
    forAll(region_, k)
    {
        if (!axes.found(region_[k]))
        {
            const labelList ps(findIndices(region_, region_[k]));
            axes.insert(region_[k], geometry_->axis(ps, vector2D::zero));
        }
    }
    forAll(ids, w)
    {
        const label k = modelIndex_[cloud_.id()[ids[w]]];
        const vector2D d(m.displacement(k));
        const symmTensor2D e(m.strain(k));
        const vector2D& t = axes[region_[k]];
        D[w] = vector(d.x(), d.y(), 0);
        theta[w] = m.theta()[k];
        omega[w] = m.omega()[k];
        exx[w] = e.xx();
        eyy[w] = e.yy();
        exy[w] = e.xy();
        axial[w] = t & (e & t);
    }
    table.add("D", std::move(D));
    table.add("theta", std::move(theta));
    table.add("omega", std::move(omega));
    table.add("strainXX", std::move(exx));
    table.add("strainYY", std::move(eyy));
    table.add("strainXY", std::move(exy));
    table.add("axialStrain", std::move(axial));
    if (m.implicit() && m.hasStepAccelerations())
    {
        // The implicit integration's state (a restart continues exactly;
        // before its first step it has none)
        vectorField A(n), L(n);
        scalarField alpha(n);
        forAll(ids, w)
        {
            const label k = modelIndex_[cloud_.id()[ids[w]]];
            const vector2D& a = m.stepAcceleration()[k];
            const vector2D& f = m.stepLoad()[k];
            A[w] = vector(a.x(), a.y(), 0);
            alpha[w] = m.stepAngularAcceleration()[k];
            L[w] = vector(f.x(), f.y(), 0);
        }
        table.add("stepAcceleration", std::move(A));
        table.add("stepAngularAcceleration", std::move(alpha));
        table.add("stepLoad", std::move(L));
    }
}


const Foam::mpsStructure& Foam::mpsStructure::lookup
(
    const objectRegistry& db
)
{
    return lookupRegistered<mpsStructure>
    (
        db,
        "structure",
        "the mpsFsiFoam solver and structure particles",
        &mpsStructure::active
    );
}


// ************************************************************************* //
