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

#include "box.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(box, 0);
    addToRunTimeSelectionTable(particleShape, box, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::box::box(const dictionary& dict)
:
    particleShape(dict),
    min_(dict.get<vector2D>("min")),
    max_(dict.get<vector2D>("max"))
{
    inputChecks::keywords
    (
        dict,
        {"type", "kind", "spacing", "min", "max"},
        "region " + dict.dictName()
    );
    if (!(max_.x() > min_.x() && max_.y() > min_.y()))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'max' " << max_ << " must exceed 'min' " << min_
            << " in both x and y" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleShapes::box::estimatedCount
(
    const scalar spacing
) const
{
    const vector2D span(max_ - min_);
    return (span.x()/spacing + 1)*(span.y()/spacing + 1);
}


void Foam::particleShapes::box::generate
(
    const scalar spacing,
    DynamicList<vector2D>& points,
    DynamicList<label>& layers
) const
{
    const label nx = label(std::round((max_.x() - min_.x())/spacing));
    const label ny = label(std::round((max_.y() - min_.y())/spacing));

    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            points.append
            (
                min_ + spacing*vector2D(i + 0.5, j + 0.5)
            );
            layers.append(0);
        }
    }
}


// ************************************************************************* //
