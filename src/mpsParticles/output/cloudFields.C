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

#include "cloudFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cloudFields::cloudFields
(
    const word& name,
    const mpsCloud& cloud,
    std::initializer_list<particleKind> kinds
)
:
    name_(name),
    regionNames_(cloud.regionNames()),
    ids_(cloud.select(kinds)),
    positions_(ids_.size())
{
    forAll(ids_, k)
    {
        const vector2D& x = cloud.x()[ids_[k]];
        positions_[k] = point(x.x(), x.y(), 0);
    }

    for (const mpsCloudField& f : cloud.fields())
    {
        if (!f.name().empty() && f.appliesTo(kinds))
        {
            f.write(ids_, *this);
        }
    }
}


// ************************************************************************* //
