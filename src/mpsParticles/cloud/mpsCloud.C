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

#include "mpsCloud.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::mpsCloud::count(const particleKind k) const
{
    label c = 0;
    for (const particleKind ki : kind_)
    {
        if (ki == k)
        {
            ++c;
        }
    }
    return c;
}


Foam::labelList Foam::mpsCloud::select
(
    std::initializer_list<particleKind> kinds
) const
{
    DynamicList<label> ids(size());
    forAll(kind_, i)
    {
        for (const particleKind k : kinds)
        {
            if (kind_[i] == k)
            {
                ids.append(i);
                break;
            }
        }
    }
    return labelList(std::move(ids));
}


Foam::label Foam::mpsCloud::addRegion(const word& name)
{
    regionNames_.append(name);
    return regionNames_.size() - 1;
}


void Foam::mpsCloud::append
(
    const vector2D& x,
    const particleKind k,
    const label regioni,
    const scalar spacing
)
{
    x_.append(x);
    U_.append(vector2D::zero);
    p_.append(0);
    n_.append(0);
    kind_.append(k);
    region_.append(regioni);
    spacing_.append(spacing);
    id_.append(id_.size());
    surface_.append(false);
}


void Foam::mpsCloud::subset(const UList<bool>& keep)
{
    label j = 0;
    forAll(x_, i)
    {
        if (keep[i])
        {
            x_[j] = x_[i];
            U_[j] = U_[i];
            p_[j] = p_[i];
            n_[j] = n_[i];
            kind_[j] = kind_[i];
            region_[j] = region_[i];
            spacing_[j] = spacing_[i];
            id_[j] = id_[i];
            surface_[j] = surface_[i];
            ++j;
        }
    }
    x_.resize(j);
    U_.resize(j);
    p_.resize(j);
    n_.resize(j);
    kind_.resize(j);
    region_.resize(j);
    spacing_.resize(j);
    id_.resize(j);
    surface_.resize(j);
}


void Foam::mpsCloud::sortByKind()
{
    labelList order(identity(size()));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [this](const label a, const label b)
        {
            return int(kind_[a]) < int(kind_[b]);
        }
    );
    auto reorder = [&order](auto& list)
    {
        auto copy(list);
        forAll(order, i)
        {
            list[i] = copy[order[i]];
        }
    };
    reorder(x_);
    reorder(U_);
    reorder(p_);
    reorder(n_);
    reorder(kind_);
    reorder(region_);
    reorder(spacing_);
    reorder(id_);
    reorder(surface_);
}


void Foam::mpsCloud::clear()
{
    x_.clear();
    U_.clear();
    p_.clear();
    n_.clear();
    kind_.clear();
    region_.clear();
    spacing_.clear();
    id_.clear();
    surface_.clear();
    regionNames_.clear();
}


// ************************************************************************* //
