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
    ids_(cloud.select(kinds)),
    positions_(ids_.size())
{
    const label n = ids_.size();
    vectorField U(n);
    scalarField p(n);
    scalarField nd(n);
    labelField kind(n);
    labelField region(n);
    labelField surface(n);
    labelField id(n);

    forAll(ids_, k)
    {
        const label i = ids_[k];
        const vector2D& x = cloud.x()[i];
        const vector2D& u = cloud.U()[i];
        positions_[k] = point(x.x(), x.y(), 0);
        U[k] = vector(u.x(), u.y(), 0);
        p[k] = cloud.p()[i];
        nd[k] = cloud.n()[i];
        kind[k] = static_cast<label>(cloud.kind()[i]);
        region[k] = cloud.region()[i];
        surface[k] = cloud.surface()[i];
        id[k] = cloud.id()[i];
    }

    vectorFields_.insert("U", std::move(U));
    scalarFields_.insert("p", std::move(p));
    scalarFields_.insert("n", std::move(nd));
    labelFields_.insert("kind", std::move(kind));
    labelFields_.insert("region", std::move(region));
    labelFields_.insert("freeSurface", std::move(surface));
    labelFields_.insert("id", std::move(id));
}


// ************************************************************************* //
