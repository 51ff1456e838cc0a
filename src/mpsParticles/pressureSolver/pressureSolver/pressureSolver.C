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
#include "inputChecks.H"
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
    tolerance_(inputChecks::number<scalar>(dict, "tolerance", 1e-8, "(0, 1)")),
    maxIter_(inputChecks::number<label>(dict, "maxIter", 2000, ">= 1"))
{}


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
