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
#include "outputClouds.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cloudFields::cloudFields
(
    const word& name,
    const mpsCloud& cloud,
    const UList<bool>& written,
    const labelUList& order
)
:
    name_(name),
    regionNames_(cloud.regionNames())
{
    DynamicList<label> ids;
    forAll(cloud.kind(), i)
    {
        if
        (
            outputClouds::holds(name, cloud.kind()[i])
         && (written.empty() || written[i])
        )
        {
            ids.append(i);
        }
    }
    if (order.size())
    {
        std::stable_sort
        (
            ids.begin(),
            ids.end(),
            [&order](const label a, const label b)
            {
                return order[a] < order[b];
            }
        );
    }
    ids_.transfer(ids);
    if (order.size())
    {
        cells_ = labelList(order, ids_);
    }

    positions_.setSize(ids_.size());
    forAll(ids_, k)
    {
        const vector2D& x = cloud.x()[ids_[k]];
        positions_[k] = point(x.x(), x.y(), 0);
    }

    // The fields that mean something for a kind the cloud holds
    for (const mpsCloudField& f : cloud.fields())
    {
        bool applies = false;
        for (int k = 0; k < nParticleKinds; ++k)
        {
            applies = applies
             || (
                    f.appliesTo(particleKind(k))
                 && outputClouds::holds(name, particleKind(k))
                );
        }
        if (!f.name().empty() && applies)
        {
            f.write(ids_, *this);
        }
    }
}


// ************************************************************************* //
