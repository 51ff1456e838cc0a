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

#include "implicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(implicitCoupling, 0);
    addToRunTimeSelectionTable(couplingScheme, implicitCoupling, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingSchemes::implicitCoupling::implicitCoupling
(
    const dictionary& dict,
    mpsFluid& fluid,
    mpsStructure& structure,
    fluidStructureInterface& interface
)
:
    couplingScheme(dict, fluid, structure, interface),
    maxIterations_(dict.getOrDefault<label>("maxIterations", 50)),
    tolerance_(dict.getOrDefault<scalar>("tolerance", 1e-3)),
    relaxation_(couplingRelaxation::New(dict)),
    lastIterations_(0),
    totalIterations_(0),
    nUnconverged_(0)
{
    if (interface.fluidPressure())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'scheme' implicit needs 'wallPressure' solved: the"
            << " fluid's pressure gradients (wallPressure fluid) are"
            << " computed in the fluid's correction, after the iterations"
            << exit(FatalIOError);
    }
    if (maxIterations_ < 1 || !(tolerance_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'maxIterations' (at least 1, got " << maxIterations_
            << ") and 'tolerance' (above 0, got " << tolerance_ << ")"
            << exit(FatalIOError);
    }
    Info<< "Coupling relaxation ";
    relaxation_->info(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::couplingSchemes::implicitCoupling::iterate
(
    const scalar t,
    const scalar deltaT
)
{
    // The walls' velocities enter the pressure through the divergence.
    // Every rank holds the whole guess
    List<vector2D> guess(interface_.wallVelocities()), x, U;
    List<vector2D> r(guess.size());
    structure_.saveState();
    relaxation_->beginStep();
    bool converged = false;
    lastIterations_ = 0;
    while (!converged && lastIterations_ < maxIterations_)
    {
        ++lastIterations_;
        interface_.setWallVelocities(guess);
        fluid_.solveStepPressure(deltaT);
        interface_.transferPressure(fluid_);
        if (lastIterations_ > 1)
        {
            // (the forces took the walls' normals where the last
            // iteration left them)
            structure_.restoreState();
        }
        advanceStructure(structure_, t, deltaT, interface_.force());
        interface_.wallMotion(x, U);

        scalar r2 = 0, U2 = 0;
        forAll(r, k)
        {
            r[k] = U[k] - guess[k];
            r2 += magSqr(r[k]);
            U2 += magSqr(U[k]);
        }
        converged = r2 <= sqr(tolerance_)*max(U2, VSMALL);
        if (!converged)
        {
            relaxation_->update(guess, r);
        }
    }
    relaxation_->endStep();
    return converged;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::mpsFluid::stepInfo&
Foam::couplingSchemes::implicitCoupling::evolve
(
    const scalar t,
    const scalar deltaT
)
{
    if (!fluid_.beginStep(deltaT))
    {
        if (fluid_.info().finite)
        {
            // No fluid: the structure under the walls' last pressures
            interface_.transferPressure(fluid_);
            advanceStructure(structure_, t, deltaT, interface_.force());
            interface_.moveWalls();
        }
        return fluid_.info();
    }

    const bool converged = iterate(t, deltaT);
    totalIterations_ += lastIterations_;
    nUnconverged_ += !converged;

    const mpsFluid::stepInfo& info = fluid_.endStep(deltaT);
    interface_.moveWalls();
    return info;
}


void Foam::couplingSchemes::implicitCoupling::info(Ostream& os) const
{
    os  << "Coupling: " << lastIterations_ << " iterations" << nl;
}


void Foam::couplingSchemes::implicitCoupling::report(Ostream& os) const
{
    os  << "Implicit coupling: " << totalIterations_ << " iterations, "
        << nUnconverged_ << " steps stopped at maxIterations" << nl;
}


// ************************************************************************* //
