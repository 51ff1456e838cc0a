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

#include "pressureSolver.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(pressureSolver, 0);
    defineRunTimeSelectionTable(pressureSolver, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pressureSolver::pressureSolver(const dictionary& dict)
:
    dict_(dict),
    tolerance_(dict.getOrDefault<scalar>("tolerance", 1e-8)),
    maxIter_(dict.getOrDefault<label>("maxIter", 2000))
{
    if (!(tolerance_ > 0 && tolerance_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'tolerance' (relative residual) must lie in (0, 1), got "
            << tolerance_ << exit(FatalIOError);
    }
    if (maxIter_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'maxIter' must be at least 1, got " << maxIter_
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::pressureSolver::performance Foam::pressureSolver::solve
(
    const ppeMatrix& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& p,
    const label rowStart
)
{
    if (Pstream::parRun() && Pstream::nProcs() > 1)
    {
        FatalIOErrorInFunction(dict_)
            << "pressureSolver " << dict_.get<word>("type")
            << " solves on one rank; under -parallel use type BoomerAMG"
            << exit(FatalIOError);
    }
    return solve(A, b, p);
}


// ************************************************************************* //
