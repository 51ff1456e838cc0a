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

#include "outputClouds.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

const Foam::wordList& Foam::outputClouds::names()
{
    static const wordList list({"fluid", "wall", "structure"});
    return list;
}


bool Foam::outputClouds::holds(const word& cloudName, const particleKind k)
{
    switch (k)
    {
        case particleKind::fluid: return cloudName == "fluid";
        case particleKind::wall:
        case particleKind::dummy: return cloudName == "wall";
        case particleKind::structure: return cloudName == "structure";
    }
    return false;
}


// ************************************************************************* //
