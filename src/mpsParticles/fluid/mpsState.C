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

#include "mpsState.H"
#include "lookupRegistered.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(mpsState, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsState::mpsState
(
    const objectRegistry& db,
    const mpsCloud& cloud,
    const mpsFluid& fluid
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
    fluid_(fluid)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::mpsState& Foam::mpsState::lookup(const objectRegistry& db)
{
    return lookupRegistered<mpsState>
    (
        db, "MPS particles", "the mpsFsiFoam solver"
    );
}


// ************************************************************************* //
