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

#include "fluidStructureInterface.H"
#include "mpsState.H"
#include "Time.H"
#include "clockValue.H"
#include "allRanks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(fluidStructureInterface, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::fluidStructureInterface::attachedHere
(
    boolList& owned
) const
{
    labelList index(attachedId_.size());
    owned.setSize(attachedId_.size());
    forAll(attachedId_, k)
    {
        index[k] = cloud_.index(attachedId_[k]);
        owned[k] = index[k] >= 0 && !cloud_.halo()[index[k]];
    }
    return index;
}


void Foam::fluidStructureInterface::setInterface(const dictionary& dict)
{
    const structureModel& model = structure_.model();
    const structureGeometry& geometry = structure_.geometry();
    const List<vector2D>& X = model.X();
    const scalar ds = model.spacing();
    const label nS = X.size();
    const labelList attached(cloud_.indices(attachedId_, "attached wall"));

    // Anchors: the nearest structural particle in the reference state
    anchor_.setSize(attached.size());
    offset_.setSize(attached.size());
    wallX_.setSize(attached.size());
    DynamicList<label> walls;
    forAll(attached, k)
    {
        const label i = attached[k];
        const vector2D& Xi = cloud_.x()[i];
        scalar best = GREAT;
        forAll(X, s)
        {
            const scalar d2 = magSqr(X[s] - Xi);
            if (d2 < best)
            {
                best = d2;
                anchor_[k] = s;
            }
        }
        offset_[k] = Xi - X[anchor_[k]];
        wallX_[k] = Xi;
        if (cloud_.kind()[i] == particleKind::wall)
        {
            walls.append(k);
        }
    }
    walls_.transfer(walls);

    // Interface layer: particles on a free face towards a wall particle
    // within l0 + ds
    List<bool> inLayer(nS, false);
    for (const label k : walls_)
    {
        const vector2D& Xw = cloud_.x()[attached[k]];
        forAll(X, s)
        {
            if
            (
                magSqr(Xw - X[s]) < sqr(l0_ + ds)
             && geometry.facing(s, Xw)
            )
            {
                inLayer[s] = true;
            }
        }
    }
    const labelList layer(findIndices(inLayer, true));

    // Weights of each wall particle over the layer within r_c
    const scalar rc =
        dict.getOrDefault<scalar>("pressureRadius", 1.5)*l0_;
    if (!(rc > 0.5*(l0_ + ds)))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'pressureRadius' (" << rc/l0_ << " l0) must exceed"
            << " the distance from a wall particle to the interface layer, "
            << 0.5*(l0_ + ds)/l0_ << " l0" << exit(FatalIOError);
    }
    normal0_.setSize(walls_.size());
    weightStart_.setSize(walls_.size() + 1);
    DynamicList<label> particle;
    DynamicList<scalar> weight;
    forAll(walls_, m)
    {
        const label i = attached[walls_[m]];
        const vector2D& Xw = cloud_.x()[i];
        weightStart_[m] = particle.size();
        scalar sum = 0;
        vector2D n(Zero);
        for (const label s : layer)
        {
            const scalar r = mag(Xw - X[s]);
            if (r < rc && geometry.facing(s, Xw))
            {
                const scalar w = rc/max(r, 1e-3*ds) - 1;
                particle.append(s);
                weight.append(w);
                sum += w;
                n += w*geometry.normalTowards(s, Xw);
            }
        }
        if (sum <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "Wall particle " << cloud_.id()[i] << " at " << Xw
                << " of region " << cloud_.regionNames()[cloud_.region()[i]]
                << " has no structural interface particle within"
                << " pressureRadius " << rc/l0_ << " l0: the wall regions"
                << " of 'walls' must lie on a free face of the structure"
                << exit(FatalIOError);
        }
        for (label e = weightStart_[m]; e < particle.size(); ++e)
        {
            weight[e] /= sum;
        }
        normal0_[m] = n/max(mag(n), VSMALL);
    }
    weightStart_.last() = particle.size();
    weightParticle_.transfer(particle);
    weight_.transfer(weight);

    Info<< "Fluid-structure interface: " << attached.size()
        << " wall and dummy particles attached, " << walls_.size()
        << " wall particles on " << layer.size()
        << " interface-layer structural particles" << nl << endl;
}


void Foam::fluidStructureInterface::transferPressure()
{
    boolList owned;
    const labelList index(attachedHere(owned));
    const scalarList& theta = structure_.model().theta();

    const mpsFluid* fluid =
        fluidPressure_ ? &mpsState::lookup(db()).fluid() : nullptr;

    // The interface walls this rank owns (all of them in a serial run)
    force_ = Zero;
    wallForce_.setSize(attachedId_.size());
    wallForce_ = Zero;
    forAll(walls_, m)
    {
        const label k = walls_[m];
        if (!owned[k])
        {
            continue;
        }
        const label i = index[k];
        const vector2D n
        (
            structureModel::rotate(theta[anchor_[k]], normal0_[m])
        );
        const scalar p =
            fluidPressure_
          ? max(scalar(0), fluid->fluidPressureAt(i))
          : cloud_.p()[i];
        const vector2D F(-p*cloud_.spacing()[i]*n);
        wallForce_[k] = F;
        for (label e = weightStart_[m]; e < weightStart_[m + 1]; ++e)
        {
            force_[weightParticle_[e]] += weight_[e]*F;
        }
    }
    combineRanks(force_, plusEqOp<vector2D>());
    combineRanks(wallForce_, plusEqOp<vector2D>());

    fluidForce_ = Zero;
    for (const label k : walls_)
    {
        fluidForce_ += wallForce_[k];
    }
    vector2D sum(Zero);
    for (const vector2D& f : force_)
    {
        sum += f;
    }
    maxImbalance_ = max(maxImbalance_, mag(sum - fluidForce_));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidStructureInterface::fluidStructureInterface
(
    const objectRegistry& db,
    mpsCloud& cloud,
    mpsStructure& structure,
    const dictionary& structureProperties,
    const scalar l0
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
    structure_(structure),
    l0_(l0),
    fluidPressure_(false),
    fluidForce_(Zero),
    wallWork_(0),
    maxImbalance_(0),
    time_(0),
    implicit_(false),
    maxIterations_(50),
    tolerance_(1e-3),
    lastIterations_(0),
    totalIterations_(0),
    nUnconverged_(0)
{
    const dictionary* dictPtr = structureProperties.findDict("coupling");
    if (!dictPtr)
    {
        return;
    }
    const dictionary& dict = *dictPtr;
    const word wallPressure(dict.getOrDefault<word>("wallPressure", "solved"));
    if (wallPressure != "solved" && wallPressure != "fluid")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'wallPressure': " << wallPressure << " is not valid"
            << nl << "Valid wall pressures: (solved fluid)"
            << exit(FatalIOError);
    }
    fluidPressure_ = (wallPressure == "fluid");
    const word scheme(dict.getOrDefault<word>("scheme", "explicit"));
    if (scheme != "explicit" && scheme != "implicit")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'scheme': " << scheme << " is not valid" << nl
            << "Valid coupling schemes: (explicit implicit)"
            << exit(FatalIOError);
    }
    implicit_ = (scheme == "implicit");
    if (implicit_ && fluidPressure_)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'scheme' implicit needs 'wallPressure' solved: the"
            << " fluid's pressure gradients (wallPressure fluid) are"
            << " computed in the fluid's correction, after the iterations"
            << exit(FatalIOError);
    }
    maxIterations_ = dict.getOrDefault<label>("maxIterations", maxIterations_);
    tolerance_ = dict.getOrDefault<scalar>("tolerance", tolerance_);
    if (maxIterations_ < 1 || !(tolerance_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'maxIterations' (at least 1, got " << maxIterations_
            << ") and 'tolerance' (above 0, got " << tolerance_ << ")"
            << exit(FatalIOError);
    }
    if (!structure_.active())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling' needs structure particles: system/"
            << "particleDict has no region of kind structure"
            << exit(FatalIOError);
    }

    // Regions of kind wall or dummy, by name
    const labelList wallDummy
    (
        cloud_.select({particleKind::wall, particleKind::dummy})
    );
    const wordList valid
    (
        cloud_.regionNames({particleKind::wall, particleKind::dummy})
    );
    labelHashSet regions;
    const wordList names(dict.get<wordList>("walls"));
    if (names.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'walls' is empty: list the wall regions that follow"
            << " the structure; valid wall regions: " << valid
            << exit(FatalIOError);
    }
    for (const word& name : names)
    {
        if (!valid.found(name))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'walls': " << name << " is not a region of wall"
                << " particles in system/particleDict" << nl
                << "Valid wall regions: " << valid << exit(FatalIOError);
        }
        const label r = cloud_.regionIndex(name);
        regions.insert(r);
    }

    DynamicList<label> attached;
    for (const label i : wallDummy)
    {
        if (regions.found(cloud_.region()[i]))
        {
            attached.append(i);
        }
    }
    attachedId_ = UIndirectList<label>(cloud_.id(), attached);

    setInterface(dict);
    force_.setSize(structure_.model().size(), Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fluidStructureInterface::evolve
(
    const scalar t,
    const scalar deltaT
)
{
    if (!active())
    {
        structure_.advance(t, deltaT, List<vector2D>());
        return;
    }

    clockValue clock(true);
    transferPressure();
    time_ += clock.elapsed();

    structure_.advance(t, deltaT, force_);

    clock.update();
    moveWalls();
    time_ += clock.elapsed();
}


void Foam::fluidStructureInterface::wallMotion
(
    List<vector2D>& x,
    List<vector2D>& U
) const
{
    const structureModel& model = structure_.model();
    x.setSize(attachedId_.size());
    U.setSize(attachedId_.size());
    forAll(attachedId_, k)
    {
        const label s = anchor_[k];
        const vector2D d(structureModel::rotate(model.theta()[s], offset_[k]));
        x[k] = model.x()[s] + d;
        U[k] = model.v()[s] + model.omega()[s]*vector2D(-d.y(), d.x());
    }
}


void Foam::fluidStructureInterface::moveWalls()
{
    if (!active())
    {
        return;
    }
    List<vector2D> x, U;
    wallMotion(x, U);
    if (wallForce_.size() == x.size())
    {
        // The fluid's force on each along its motion (interface walls;
        // the others carry none)
        forAll(x, k)
        {
            wallWork_ += wallForce_[k] & (x[k] - wallX_[k]);
        }
    }
    wallX_ = x;

    boolList owned;
    const labelList index(attachedHere(owned));
    forAll(index, k)
    {
        const label i = index[k];
        if (i >= 0)
        {
            cloud_.x()[i] = x[k];
            cloud_.U()[i] = U[k];
        }
    }
}


const Foam::mpsFluid::stepInfo& Foam::fluidStructureInterface::step
(
    mpsFluid& fluid,
    const scalar t,
    const scalar deltaT
)
{
    if (!implicit_ || !active())
    {
        const mpsFluid::stepInfo& info = fluid.step(deltaT);
        if (info.finite)
        {
            evolve(t, deltaT);
        }
        return info;
    }

    if (!fluid.beginStep(deltaT))
    {
        if (fluid.info().finite)
        {
            // No fluid: the structure alone
            evolve(t, deltaT);
        }
        return fluid.info();
    }

    // Fixed point on the attached particles' velocities, which enter the
    // pressure through the divergence: the pressure solved with the walls
    // at the guessed end-of-step velocity, the structure's step under it,
    // the walls' new velocity; Aitken's relaxation (Kuettler & Wall 2008)
    // (every rank holds the whole guess: each particle's from its owner)
    boolList owned;
    const labelList index(attachedHere(owned));
    const label n = index.size();
    List<vector2D> guess(n, Zero), x, U, r(n), rOld(n);
    forAll(index, k)
    {
        if (owned[k])
        {
            guess[k] = cloud_.U()[index[k]];
        }
    }
    combineRanks(guess, plusEqOp<vector2D>());
    structure_.saveState();
    // Every iteration solves from the step's old pressure (the rate form
    // of the compressibility reads it)
    const scalarList pOld(cloud_.p());
    scalar omega = 0.5;
    lastIterations_ = 0;
    bool converged = false;
    while (lastIterations_ < maxIterations_)
    {
        ++lastIterations_;
        forAll(index, k)
        {
            if (index[k] >= 0)
            {
                cloud_.U()[index[k]] = guess[k];
            }
        }
        if (lastIterations_ > 1)
        {
            cloud_.p().deepCopy(pOld);
        }
        fluid.solveStepPressure(deltaT);

        clockValue clock(true);
        transferPressure();
        time_ += clock.elapsed();
        if (lastIterations_ > 1)
        {
            structure_.restoreState();
        }
        structure_.advance(t, deltaT, force_);
        wallMotion(x, U);

        scalar r2 = 0, U2 = 0;
        forAll(r, k)
        {
            r[k] = U[k] - guess[k];
            r2 += magSqr(r[k]);
            U2 += magSqr(U[k]);
        }
        if (r2 <= sqr(tolerance_)*max(U2, VSMALL))
        {
            converged = true;
            break;
        }
        if (lastIterations_ > 1)
        {
            scalar num = 0, den = 0;
            forAll(r, k)
            {
                const vector2D dr(r[k] - rOld[k]);
                num += rOld[k] & dr;
                den += magSqr(dr);
            }
            if (den > 0)
            {
                omega = -omega*num/den;
            }
        }
        forAll(guess, k)
        {
            guess[k] += omega*r[k];
        }
        rOld = r;
    }
    totalIterations_ += lastIterations_;
    nUnconverged_ += !converged;

    const mpsFluid::stepInfo& info = fluid.endStep(deltaT);
    clockValue clock(true);
    moveWalls();
    time_ += clock.elapsed();
    return info;
}


bool Foam::fluidStructureInterface::referencePosition
(
    const label id,
    vector2D& X
) const
{
    const label k = attachedId_.find(id);
    if (k < 0)
    {
        return false;
    }
    X = structure_.model().X()[anchor_[k]] + offset_[k];
    return true;
}


const Foam::fluidStructureInterface& Foam::fluidStructureInterface::lookup
(
    const objectRegistry& db
)
{
    const fluidStructureInterface* ptr =
        db.findObject<fluidStructureInterface>(typeName);
    if (!ptr || !ptr->active())
    {
        FatalErrorInFunction
            << "No fluid-structure interface in " << db.name() << ": this"
            << " function object needs the mpsFsiFoam solver and an entry"
            << " 'coupling' in constant/structureProperties"
            << exit(FatalError);
    }
    return *ptr;
}


// ************************************************************************* //
