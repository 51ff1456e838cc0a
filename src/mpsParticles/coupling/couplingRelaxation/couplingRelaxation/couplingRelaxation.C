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

#include "couplingRelaxation.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(couplingRelaxation, 0);
    defineRunTimeSelectionTable(couplingRelaxation, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingRelaxation::couplingRelaxation(const dictionary& dict)
:
    dict_(dict),
    initial_(inputChecks::number<scalar>(dict, "initial", 0.5, "(0, 1]"))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::couplingRelaxation::info(Ostream& os) const
{
    os  << type() << " (initial " << initial_ << ")";
}


// ************************************************************************* //
