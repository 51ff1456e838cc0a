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
#include "allRanks.H"
#include "mpsCloudListField.H"
#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::mpsCloud::addField
(
    DynamicList<Type>& list,
    const word& name,
    const bool restart,
    std::initializer_list<particleKind> kinds,
    const Type& initial
)
{
    fields_.append
    (
        new mpsCloudListField<Type>(list, name, restart, kinds, initial)
    );
}


void Foam::mpsCloud::addFields()
{
    // name, read back at a restart, the kinds it means something for, the
    // value of a new particle
    const auto all =
    {
        particleKind::fluid, particleKind::wall, particleKind::dummy,
        particleKind::structure
    };
    const auto fluidWall = {particleKind::fluid, particleKind::wall};
    addField(x_, word::null, false, all, vector2D::zero);  // as positions
    addField(U_, "U", true, all, vector2D::zero);
    addField(p_, "p", true, fluidWall, scalar(0));
    addField
    (
        n_, "n", false,
        {particleKind::fluid, particleKind::wall, particleKind::dummy},
        scalar(0)
    );
    addField(kind_, "kind", false, all, particleKind::fluid);
    addField(region_, "region", false, all, label(-1));
    addField(spacing_, word::null, false, all, scalar(0));
    addField(id_, "id", false, all, label(-1));
    addField(surface_, "freeSurface", false, fluidWall, false);
    addField(halo_, word::null, false, all, false);
}


void Foam::mpsCloud::reorder(const labelUList& from)
{
    for (mpsCloudField& f : fields_)
    {
        f.reorder(from);
    }
    updateIndex();
}


void Foam::mpsCloud::updateIndex()
{
    ++revision_;
    start_ = 0;
    forAll(kind_, i)
    {
        if (i > 0 && int(kind_[i]) < int(kind_[i - 1]))
        {
            FatalErrorInFunction
                << "Particles out of kind order at index " << i
                << exit(FatalError);
        }
        ++start_[int(kind_[i]) + 1];
    }
    for (int k = 1; k <= nParticleKinds; ++k)
    {
        start_[k] += start_[k - 1];
    }

    indexOfId_ = -1;
    forAll(id_, i)
    {
        indexOfId_[id_[i]] = i;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsCloud::mpsCloud()
:
    start_(0),
    revision_(0),
    distribution_(nullptr)
{
    addFields();
}


Foam::mpsCloud::mpsCloud(const mpsCloud& cloud)
:
    x_(cloud.x_),
    U_(cloud.U_),
    p_(cloud.p_),
    n_(cloud.n_),
    kind_(cloud.kind_),
    region_(cloud.region_),
    spacing_(cloud.spacing_),
    id_(cloud.id_),
    surface_(cloud.surface_),
    halo_(cloud.halo_),
    start_(cloud.start_),
    indexOfId_(cloud.indexOfId_),
    regionNames_(cloud.regionNames_),
    revision_(cloud.revision_),
    distribution_(nullptr)
{
    addFields();
}


Foam::mpsCloud::mpsCloud(mpsCloud&& cloud)
:
    x_(std::move(cloud.x_)),
    U_(std::move(cloud.U_)),
    p_(std::move(cloud.p_)),
    n_(std::move(cloud.n_)),
    kind_(std::move(cloud.kind_)),
    region_(std::move(cloud.region_)),
    spacing_(std::move(cloud.spacing_)),
    id_(std::move(cloud.id_)),
    surface_(std::move(cloud.surface_)),
    halo_(std::move(cloud.halo_)),
    start_(cloud.start_),
    indexOfId_(std::move(cloud.indexOfId_)),
    regionNames_(std::move(cloud.regionNames_)),
    revision_(cloud.revision_),
    distribution_(nullptr)
{
    addFields();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mpsCloud::setDistribution(cloudDistribution& distribution)
{
    distribution_ = &distribution;
    distribute();
}


void Foam::mpsCloud::distribute()
{
    if (distribution_)
    {
        distribution_->distribute(*this);
    }
}


void Foam::mpsCloud::localise()
{
    if (distribution_)
    {
        distribute();
        for (const std::function<void()>& f : onLocalise_)
        {
            f();
        }
    }
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


Foam::wordList Foam::mpsCloud::regionNames
(
    std::initializer_list<particleKind> kinds
) const
{
    List<bool> holds(regionNames_.size(), false);
    for (const label i : select(kinds))
    {
        holds[region_[i]] = true;
    }
    // Those of every rank (a region can lie on other ranks only)
    combineRanks(holds, orEqOp<bool>());
    DynamicList<word> names;
    forAll(holds, r)
    {
        if (holds[r])
        {
            names.append(regionNames_[r]);
        }
    }
    return wordList(std::move(names));
}


Foam::labelList Foam::mpsCloud::indices
(
    const labelUList& ids,
    const char* what
) const
{
    labelList result(ids.size());
    forAll(ids, k)
    {
        result[k] = index(ids[k]);
        if (result[k] < 0)
        {
            FatalErrorInFunction
                << "Particle id " << ids[k] << " (" << what << ") is not in"
                << " the cloud" << exit(FatalError);
        }
    }
    return result;
}


Foam::label Foam::mpsCloud::addRegion(const word& name)
{
    regionNames_.append(name);
    return regionNames_.size() - 1;
}


void Foam::mpsCloud::append
(
    const UList<vector2D>& x,
    const UList<particleKind>& k,
    const label regioni,
    const scalar spacing
)
{
    const label n0 = size();
    const label n = n0 + x.size();
    for (mpsCloudField& f : fields_)
    {
        f.resize(n);
    }
    const label id0 = indexOfId_.size();
    indexOfId_.resize(id0 + x.size());
    forAll(x, j)
    {
        const label i = n0 + j;
        x_[i] = x[j];
        kind_[i] = k[j];
        region_[i] = regioni;
        spacing_[i] = spacing;
        id_[i] = id0 + j;
    }

    ++revision_;

    // In kind order if no new kind is below the one before it
    bool inOrder = true;
    particleKind last = n0 ? kind_[n0 - 1] : particleKind::fluid;
    for (const particleKind kj : k)
    {
        inOrder = inOrder && int(kj) >= int(last);
        last = kj;
    }

    if (!inOrder)
    {
        // The new particles go after the others of their kind
        labelList order(identity(n));
        std::stable_sort
        (
            order.begin(),
            order.end(),
            [this](const label a, const label b)
            {
                return int(kind_[a]) < int(kind_[b]);
            }
        );
        reorder(order);
    }
    else
    {
        // In order: the ranges after each new particle's kind grow, the
        // new ids index the end
        forAll(x, j)
        {
            for (int kk = int(k[j]) + 1; kk <= nParticleKinds; ++kk)
            {
                ++start_[kk];
            }
            indexOfId_[id0 + j] = n0 + j;
        }
    }
}


void Foam::mpsCloud::append
(
    const UList<vector2D>& x,
    const particleKind k,
    const label regioni,
    const scalar spacing
)
{
    append(x, List<particleKind>(x.size(), k), regioni, spacing);
}


void Foam::mpsCloud::append
(
    const vector2D& x,
    const particleKind k,
    const label regioni,
    const scalar spacing
)
{
    append(List<vector2D>(1, x), k, regioni, spacing);
}


void Foam::mpsCloud::subset(const UList<bool>& keep)
{
    reorder(findIndices(keep, true));
}


void Foam::mpsCloud::send(const labelUList& index, Ostream& os) const
{
    for (const mpsCloudField& f : fields_)
    {
        f.send(index, os);
    }
}


Foam::labelList Foam::mpsCloud::receive(Istream& is)
{
    const label n0 = size();
    for (mpsCloudField& f : fields_)
    {
        f.receive(is);
    }
    const label n = x_.size(), nNew = n - n0;
    if (id_.size() != n || kind_.size() != n || halo_.size() != n)
    {
        FatalErrorInFunction
            << "Received " << nNew << " positions but "
            << id_.size() - n0 << " ids, " << kind_.size() - n0
            << " kinds: not what one send wrote" << exit(FatalError);
    }

    labelList ids(SubList<label>(id_, nNew, n0));
    const label known = indexOfId_.size();
    label idEnd = known;
    for (const label id : ids)
    {
        if (id < known && indexOfId_[id] >= 0)
        {
            FatalErrorInFunction
                << "Received particle id " << id << ", which this cloud"
                << " already holds" << exit(FatalError);
        }
        idEnd = max(idEnd, id + 1);
    }
    indexOfId_.resize(idEnd, -1);

    // The new particles go after the others of their kind
    labelList order(identity(n));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [this](const label a, const label b)
        {
            return int(kind_[a]) < int(kind_[b]);
        }
    );
    reorder(order);
    return ids;
}


void Foam::mpsCloud::clear()
{
    for (mpsCloudField& f : fields_)
    {
        f.clear();
    }
    indexOfId_.clear();
    regionNames_.clear();
    start_ = 0;
    ++revision_;
}


// ************************************************************************* //
