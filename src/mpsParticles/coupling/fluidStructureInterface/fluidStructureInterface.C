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
#include "lookupRegistered.H"
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


Foam::List<Foam::vector2D>
Foam::fluidStructureInterface::wallVelocities() const
{
    boolList owned;
    const labelList index(attachedHere(owned));
    List<vector2D> U(index.size(), Zero);
    forAll(index, k)
    {
        if (owned[k])
        {
            U[k] = cloud_.U()[index[k]];
        }
    }
    combineRanks(U, plusEqOp<vector2D>());
    return U;
}


void Foam::fluidStructureInterface::setWallVelocities
(
    const UList<vector2D>& U
)
{
    forAll(attachedId_, k)
    {
        const label i = cloud_.index(attachedId_[k]);
        if (i >= 0)
        {
            cloud_.U()[i] = U[k];
        }
    }
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


void Foam::fluidStructureInterface::transferPressure(const mpsFluid& fluid)
{
    const clockValue clock(true);
    boolList owned;
    const labelList index(attachedHere(owned));
    const scalarList& theta = structure_.model().theta();

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
          ? max(scalar(0), fluid.fluidPressureAt(i))
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
    time_ += clock.elapsed();
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
    time_(0)
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
    const clockValue clock(true);
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
    time_ += clock.elapsed();
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
    return lookupRegistered<fluidStructureInterface>
    (
        db,
        "fluid-structure interface",
        "the mpsFsiFoam solver and an entry 'coupling' in"
        " constant/structureProperties",
        &fluidStructureInterface::active
    );
}


// ************************************************************************* //
