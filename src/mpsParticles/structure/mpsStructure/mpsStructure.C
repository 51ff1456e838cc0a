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
#include "cloudFields.H"
#include "neighbourList.H"
#include "Time.H"
#include "clockValue.H"
#include "Map.H"
#include "IOField.H"
#include "cloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(mpsStructure, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mpsStructure::mapToCloud()
{
    // Structure particles are never removed and the cloud keeps the order
    // of the particles it keeps, so the k-th structure particle of the
    // cloud is always particle k of the model
    cloudIndex_ = cloud_.select({particleKind::structure});
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


Foam::label Foam::mpsStructure::regionIndex
(
    const word& name,
    const dictionary& dict
) const
{
    DynamicList<word> valid;
    forAll(cloud_.regionNames(), r)
    {
        if (region_.found(r))
        {
            if (cloud_.regionNames()[r] == name)
            {
                return r;
            }
            valid.append(cloud_.regionNames()[r]);
        }
    }
    FatalIOErrorInFunction(dict)
        << "Unknown structure region " << name << " in " << dict.name()
        << nl << "Valid structure regions of system/particleDict: "
        << valid << exit(FatalIOError);
    return -1;
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
    fluidDeltaT_(-1),
    nSubSteps_(0),
    totalSubSteps_(0),
    wallTime_(0)
{
    mapToCloud();
    if (cloudIndex_.empty())
    {
        return;
    }
    if (!dict_.found("structureModel"))
    {
        FatalIOErrorInFunction(dict_)
            << "The case has " << cloudIndex_.size() << " structure"
            << " particles: constant/structureProperties needs an entry"
            << " structureModel (rotatingParticles, totalLagrangian, rigid)"
            << exit(FatalIOError);
    }

    const label n = cloudIndex_.size();
    List<vector2D> X(n);
    region_.setSize(n);
    scalar ds = 0;
    forAll(cloudIndex_, k)
    {
        const label i = cloudIndex_[k];
        X[k] = cloud_.x()[i];
        region_[k] = cloud_.region()[i];
        ds = cloud_.spacing()[i];
    }

    // Clamped regions
    List<bool> clamped(n, false);
    const wordList clampedRegions
    (
        dict_.getOrDefault<wordList>("clamped", wordList())
    );
    for (const word& name : clampedRegions)
    {
        const label r = regionIndex(name, dict_);
        forAll(region_, k)
        {
            clamped[k] = clamped[k] || region_[k] == r;
        }
    }

    model_ = structureModel::New(dict_, X, clamped, ds);
    model_->setClampedVelocity
    (
        dict_.getOrDefault<vector2D>("clampedVelocity", vector2D::zero)
    );
    fluidForce_.setSize(n, Zero);
    totalFluidForce_ = Zero;

    if (dict_.found("bodyMotion"))
    {
        if (dict_.found("clampedVelocity") || !clampedRegions.size())
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'bodyMotion' moves the clamped regions: it needs"
                << " an entry 'clamped' (the regions it moves) and no entry"
                << " 'clampedVelocity'" << exit(FatalIOError);
        }
        motion_ = bodyMotion::New(dict_, db.time().value());
        model_->setClampedVelocity(motion_->velocity());

        // The body moves as a whole at the start (the wedge dropped onto
        // the water), unless initialVelocity says otherwise below
        model_->v() = motion_->velocity();
    }

    if (dict_.found("initialVelocity"))
    {
        setInitialVelocity(dict_.subDict("initialVelocity"));
    }

    // Loads
    if (dict_.found("loads"))
    {
        const dictionary& loadsDict = dict_.subDict("loads");
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
            load->particles = surfaceLayer
            (
                regionParticles(d.get<word>("region"), d),
                load->normal
            );
            load->pressure = Function1<scalar>::New("pressure", d);
            Info<< "Structure load " << load->name << ": pressure on "
                << load->particles.size() << " particles of region "
                << d.get<word>("region") << " facing " << load->normal
                << endl;
            loads_.append(load);
        }
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

void Foam::mpsStructure::advance(const scalar t, const scalar fluidDeltaT)
{
    if (!active())
    {
        return;
    }
    clockValue clock(true);

    if (mag(fluidDeltaT - fluidDeltaT_) > 1e-12*fluidDeltaT)
    {
        nSubSteps_ = model_->setSubSteps(fluidDeltaT);
        fluidDeltaT_ = fluidDeltaT;
    }

    // The body's motion over the step, under the fluid force just solved
    if (motion_.valid())
    {
        motion_->update(t, fluidDeltaT, totalFluidForce_);
        model_->setClampedVelocity(motion_->velocity());
    }

    // Fluid forces and loads at the end of the fluid step, held over the
    // sub-steps
    List<vector2D>& f = model_->externalForce();
    f = fluidForce_;
    const scalar ds = model_->spacing();
    for (const surfaceLoad& load : loads_)
    {
        const scalar p = load.pressure->value(t);
        for (const label k : load.particles)
        {
            f[k] -= (p*ds)*load.normal;
        }
    }
    model_->evaluate();
    model_->advance(nSubSteps_);
    totalSubSteps_ += nSubSteps_;

    forAll(model_->x(), k)
    {
        const vector2D& x = model_->x()[k];
        if (!std::isfinite(x.x()) || !std::isfinite(x.y()))
        {
            FatalErrorInFunction
                << "The structure diverged in the fluid step ending at"
                << " time " << t << ": particle " << k << " (reference "
                << model_->X()[k] << ") is not finite. Nothing of this"
                << " step was written; the last written time is intact."
                << exit(FatalError);
        }
    }

    toCloud();
    wallTime_ += clock.elapsed();
}


void Foam::mpsStructure::setFluidForce(const UList<vector2D>& f)
{
    fluidForce_ = f;
    totalFluidForce_ = Zero;
    for (const vector2D& fk : fluidForce_)
    {
        totalFluidForce_ += fk;
    }
}


void Foam::mpsStructure::toCloud()
{
    if (!active())
    {
        return;
    }
    mapToCloud();
    forAll(cloudIndex_, k)
    {
        const label i = cloudIndex_[k];
        cloud_.x()[i] = model_->x()[k];
        cloud_.U()[i] = model_->v()[k];
    }
}


void Foam::mpsStructure::readRestart(const polyMesh& mesh)
{
    if (!active())
    {
        return;
    }
    const word& timeName = mesh.time().timeName();
    const fileName local(cloud::prefix/"structure");
    auto io = [&](const word& name)
    {
        return IOobject
        (
            name, timeName, local, mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
    };
    const IOField<label> id(io("id"));
    const IOField<vector> D(io("D"));
    const IOField<vector> U(io("U"));
    const IOField<scalar> theta(io("theta"));
    const IOField<scalar> omega(io("omega"));

    // model index of each particle id
    mapToCloud();
    Map<label> indexOfId;
    forAll(cloudIndex_, k)
    {
        indexOfId.insert(cloud_.id()[cloudIndex_[k]], k);
    }
    structureModel& m = model_();
    if (id.size() != m.size())
    {
        FatalErrorInFunction
            << "The structure written at time " << timeName << " has "
            << id.size() << " particles, the case generates " << m.size()
            << exit(FatalError);
    }
    forAll(id, w)
    {
        const auto iter = indexOfId.cfind(id[w]);
        if (!iter.found())
        {
            FatalErrorInFunction
                << "Structure particle id " << id[w] << " written at time "
                << timeName << " is not generated by system/particleDict"
                << exit(FatalError);
        }
        const label k = iter.val();
        m.x()[k] = m.X()[k] + vector2D(D[w].x(), D[w].y());
        m.v()[k] = vector2D(U[w].x(), U[w].y());
        m.theta()[k] = theta[w];
        m.omega()[k] = omega[w];
    }
    m.setTime(mesh.time().value());
    m.restored();
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


Foam::labelList Foam::mpsStructure::surfaceLayer
(
    const labelList& particles,
    const vector2D& n
) const
{
    const List<vector2D>& X = model_->X();
    const scalar ds = model_->spacing();
    const neighbourList nbrs(X, 1.5*ds);
    DynamicList<label> layer;
    for (const label i : particles)
    {
        bool covered = false;
        for (label e = nbrs.offsets()[i]; e < nbrs.offsets()[i + 1]; ++e)
        {
            if (((X[nbrs.neighbours()[e]] - X[i]) & n) > 0.5*ds)
            {
                covered = true;
                break;
            }
        }
        if (!covered)
        {
            layer.append(i);
        }
    }
    return labelList(std::move(layer));
}


Foam::vector2D Foam::mpsStructure::axis
(
    const labelList& particles,
    const vector2D& end
) const
{
    const List<vector2D>& X = model_->X();
    vector2D mean(Zero);
    for (const label i : particles)
    {
        mean += X[i];
    }
    mean /= max(particles.size(), label(1));
    scalar xx = 0, xy = 0, yy = 0;
    for (const label i : particles)
    {
        const vector2D d(X[i] - mean);
        xx += d.x()*d.x();
        xy += d.x()*d.y();
        yy += d.y()*d.y();
    }
    vector2D a(structureModel::principalAxis(xx, xy, yy));
    if (((mean - end) & a) < 0)
    {
        a = -a;
    }
    return a;
}


void Foam::mpsStructure::addFields(cloudFields& fields) const
{
    if (!active())
    {
        return;
    }
    const structureModel& m = model_();
    const label n = m.size();
    vectorField D(n);
    scalarField theta(n), omega(n), exx(n), eyy(n), exy(n), axial(n);

    // axial strain along the long axis of each region
    Map<vector2D> axes;
    forAll(region_, k)
    {
        if (!axes.found(region_[k]))
        {
            const labelList ps(findIndices(region_, region_[k]));
            axes.insert(region_[k], axis(ps, vector2D::zero));
        }
    }
    for (label k = 0; k < n; ++k)
    {
        const vector2D d(m.displacement(k));
        const symmTensor2D e(m.strain(k));
        const vector2D& t = axes[region_[k]];
        D[k] = vector(d.x(), d.y(), 0);
        theta[k] = m.theta()[k];
        omega[k] = m.omega()[k];
        exx[k] = e.xx();
        eyy[k] = e.yy();
        exy[k] = e.xy();
        axial[k] = t & (e & t);
    }
    fields.add("D", D);
    fields.add("theta", theta);
    fields.add("omega", omega);
    fields.add("strainXX", exx);
    fields.add("strainYY", eyy);
    fields.add("strainXY", exy);
    fields.add("axialStrain", axial);
}


Foam::mpsStructure& Foam::mpsStructure::New(const objectRegistry& db)
{
    mpsStructure* ptr = db.getObjectPtr<mpsStructure>(typeName);
    if (!ptr || !ptr->active())
    {
        FatalErrorInFunction
            << "No structure in " << db.name() << ": this function object"
            << " works with the mpsFsiFoam solver and structure particles"
            << exit(FatalError);
    }
    return *ptr;
}


// ************************************************************************* //
