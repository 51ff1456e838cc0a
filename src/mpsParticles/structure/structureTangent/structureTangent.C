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

#include "structureTangent.H"
#include "neighbourList.H"
#include "Random.H"
#include "error.H"

#include <string>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::structureTangent::influenceRadius
(
    const UList<vector2D>& x,
    const UList<scalar>& theta,
    const forceFunction& forces
)
{
    // The free particle nearest the centre of the structure
    vector2D centre(Zero);
    forAll(X_, i)
    {
        centre += X_[i];
    }
    centre /= max(X_.size(), label(1));
    label p = -1;
    forAll(X_, i)
    {
        if
        (
            dof_[i] >= 0
         && (p < 0 || magSqr(X_[i] - centre) < magSqr(X_[p] - centre))
        )
        {
            p = i;
        }
    }
    if (p < 0)
    {
        return ds_;
    }

    const label n = X_.size();
    List<vector2D> F0(n), F1(n);
    scalarList T0(n), T1(n);
    forces(x, theta, F0, T0);
    List<vector2D> xp(x);
    scalarList thetap(theta);
    xp[p] += vector2D(1e-3*ds_, 1e-3*ds_);
    thetap[p] += 1e-3;
    forces(xp, thetap, F1, T1);
    nEvaluations_ += 2;

    scalar R = 0;
    forAll(X_, i)
    {
        if (F1[i] != F0[i] || T1[i] != T0[i])
        {
            R = max(R, mag(X_[i] - X_[p]));
        }
    }
    return max(R, ds_);
}


void Foam::structureTangent::colour(const scalar radius)
{
    const neighbourList nbrs(X_, 2*radius);
    labelList colourOf(X_.size(), -1);
    DynamicList<DynamicList<label>> colours;
    forAll(X_, i)
    {
        if (dof_[i] < 0)
        {
            continue;
        }
        List<bool> taken(colours.size(), false);
        for (const label j : nbrs[i])
        {
            if (colourOf[j] >= 0)
            {
                taken[colourOf[j]] = true;
            }
        }
        label c = 0;
        while (c < taken.size() && taken[c])
        {
            ++c;
        }
        if (c == colours.size())
        {
            colours.append(DynamicList<label>());
        }
        colours[c].append(i);
        colourOf[i] = c;
    }
    colours_.setSize(colours.size());
    forAll(colours, c)
    {
        colours_[c] = colours[c];
    }
}


void Foam::structureTangent::findParts(const neighbourList& nbrs)
{
    // Union-find over the pairs of free particles
    labelList root(X_.size());
    forAll(root, i)
    {
        root[i] = i;
    }
    auto find = [&root](label i)
    {
        while (root[i] != i)
        {
            root[i] = root[root[i]];
            i = root[i];
        }
        return i;
    };
    forAll(X_, i)
    {
        if (dof_[i] < 0)
        {
            continue;
        }
        for (const label j : nbrs[i])
        {
            if (dof_[j] >= 0)
            {
                const label a = find(i), b = find(j);
                root[max(a, b)] = min(a, b);
            }
        }
    }

    // The parts in the order of their first particles, each in increasing
    // order
    labelList partOf(X_.size(), -1);
    DynamicList<DynamicList<label>> parts;
    forAll(X_, i)
    {
        if (dof_[i] < 0)
        {
            continue;
        }
        const label r = find(i);
        if (partOf[r] < 0)
        {
            partOf[r] = parts.size();
            parts.append(DynamicList<label>());
        }
        parts[partOf[r]].append(i);
    }
    parts_.setSize(parts.size());
    partDof_.setSize(nDof_);
    forAll(parts, p)
    {
        parts_[p] = parts[p];
        forAll(parts_[p], k)
        {
            for (label a = 0; a < 3; ++a)
            {
                partDof_[dof_[parts_[p][k]] + a] = 3*k + a;
            }
        }
    }
}


Eigen::SparseMatrix<double> Foam::structureTangent::block
(
    const Eigen::SparseMatrix<double>& M,
    const label p
) const
{
    // M has no entries between parts: a column of part p has its rows in
    // p, in the same order
    const labelList& part = parts_[p];
    Eigen::SparseMatrix<double> B(3*part.size(), 3*part.size());
    std::vector<Eigen::Triplet<double>> entries;
    forAll(part, k)
    {
        for (label a = 0; a < 3; ++a)
        {
            const label g = dof_[part[k]] + a;
            for (Eigen::SparseMatrix<double>::InnerIterator it(M, g); it; ++it)
            {
                entries.emplace_back(partDof_[it.row()], 3*k + a, it.value());
            }
        }
    }
    B.setFromTriplets(entries.begin(), entries.end());
    B.makeCompressed();
    return B;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureTangent::structureTangent
(
    const UList<vector2D>& X,
    const UList<bool>& fixed,
    const scalar spacing
)
:
    X_(X),
    dof_(X.size(), -1),
    nDof_(0),
    ds_(spacing),
    colours_(),
    radius_(0),
    parts_(),
    partDof_(),
    K_(),
    ldlt_(),
    lu_(),
    nEvaluations_(0)
{
    forAll(X_, i)
    {
        if (!fixed[i])
        {
            dof_[i] = nDof_;
            nDof_ += 3;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::structureTangent::build
(
    const UList<vector2D>& x,
    const UList<scalar>& theta,
    const forceFunction& forces
)
{
    const bool first = colours_.empty();
    if (first)
    {
        radius_ = 2*influenceRadius(x, theta, forces);
        colour(radius_);
    }

    const label n = X_.size();
    const scalar hx = 1e-7*ds_, ht = 1e-7;
    List<vector2D> F0(n), F1(n);
    scalarList T0(n), T1(n);
    forces(x, theta, F0, T0);
    ++nEvaluations_;

    // Each particle's neighbours within the influence radius, itself too
    const neighbourList nbrs(X_, radius_);
    if (first)
    {
        findParts(nbrs);
    }
    labelList colourOf(n, -1);
    forAll(colours_, c)
    {
        for (const label i : colours_[c])
        {
            colourOf[i] = c;
        }
    }

    std::vector<Eigen::Triplet<double>> triplets;
    List<vector2D> xp(x);
    scalarList thetap(theta);
    forAll(colours_, c)
    {
        const labelList& moved = colours_[c];
        for (label comp = 0; comp < 3; ++comp)
        {
            const scalar h = comp < 2 ? hx : ht;
            for (const label j : moved)
            {
                if (comp < 2)
                {
                    xp[j][comp] += h;
                }
                else
                {
                    thetap[j] += h;
                }
            }
            forces(xp, thetap, F1, T1);
            ++nEvaluations_;
            for (const label j : moved)
            {
                xp[j] = x[j];
                thetap[j] = theta[j];
            }

            // Each free particle's change, to the moved particle near it
            for (label i = 0; i < n; ++i)
            {
                if (dof_[i] < 0)
                {
                    continue;
                }
                label j = (colourOf[i] == c) ? i : -1;
                for (const label k : nbrs[i])
                {
                    if (j < 0 && colourOf[k] == c)
                    {
                        j = k;
                    }
                }
                if (j < 0)
                {
                    continue;
                }
                const scalar d[3] =
                {
                    F1[i].x() - F0[i].x(),
                    F1[i].y() - F0[i].y(),
                    T1[i] - T0[i]
                };
                for (label a = 0; a < 3; ++a)
                {
                    if (!std::isfinite(d[a]))
                    {
                        FatalErrorInFunction
                            << "The structure's internal forces are not"
                            << " finite about the configuration its tangent"
                            << " is built at (particle " << i << " at "
                            << x[i] << ")" << exit(FatalError);
                    }
                    if (d[a] != 0)
                    {
                        triplets.emplace_back
                        (
                            dof_[i] + a, dof_[j] + comp, -d[a]/h
                        );
                    }
                }
            }
        }
    }
    K_.resize(nDof_, nDof_);
    K_.setFromTriplets(triplets.begin(), triplets.end());
    ldlt_.clear();
    lu_.clear();

    if (!first)
    {
        return;
    }

    // Check: K v against the forces' change along a random v
    Random rnd(4321);
    Eigen::VectorXd v(nDof_);
    forAll(X_, i)
    {
        if (dof_[i] >= 0)
        {
            const vector2D dx
            (
                hx*(rnd.sample01<scalar>() - 0.5),
                hx*(rnd.sample01<scalar>() - 0.5)
            );
            const scalar dt = ht*(rnd.sample01<scalar>() - 0.5);
            xp[i] += dx;
            thetap[i] += dt;
            v(dof_[i]) = dx.x();
            v(dof_[i] + 1) = dx.y();
            v(dof_[i] + 2) = dt;
        }
    }
    forces(xp, thetap, F1, T1);
    ++nEvaluations_;
    const Eigen::VectorXd Kv(K_*v);
    scalar err = 0, norm = 0;
    forAll(X_, i)
    {
        if (dof_[i] >= 0)
        {
            const label k = dof_[i];
            err +=
                sqr(-(F1[i].x() - F0[i].x()) - Kv(k))
              + sqr(-(F1[i].y() - F0[i].y()) - Kv(k + 1))
              + sqr(ds_*(-(T1[i] - T0[i]) - Kv(k + 2)));
            norm += sqr(Kv(k)) + sqr(Kv(k + 1)) + sqr(ds_*Kv(k + 2));
        }
    }
    if (!(err <= sqr(1e-4)*norm))
    {
        FatalErrorInFunction
            << "The structure's tangent stiffness by finite differences"
            << " (" << colours_.size() << " colours, influence radius "
            << radius_/ds_ << " spacings) misses the forces' change along a"
            << " random displacement by " << ::sqrt(err/max(norm, VSMALL))
            << " of it: a stencil wider than measured" << exit(FatalError);
    }
}


void Foam::structureTangent::factorise
(
    const scalar cM,
    const scalar cK,
    const scalar m,
    const scalar I
)
{
    // Each part's block on a thread (K has no entries between parts):
    // LDL^T, or LU of the unsymmetrised block where LDL^T meets a zero pivot
    const label nParts = parts_.size();
    ldlt_.clear();
    ldlt_.resize(nParts);
    lu_.clear();
    lu_.resize(nParts);
    labelList singular(nParts, 0);
    std::vector<std::string> message(nParts);

    #pragma omp parallel for schedule(dynamic, 1)
    for (label p = 0; p < nParts; ++p)
    {
        const label n = 3*parts_[p].size();
        Eigen::SparseMatrix<double> D(n, n);
        std::vector<Eigen::Triplet<double>> diag;
        diag.reserve(n);
        for (label k = 0; k < n; k += 3)
        {
            diag.emplace_back(k, k, cM*m);
            diag.emplace_back(k + 1, k + 1, cM*m);
            diag.emplace_back(k + 2, k + 2, cM*I);
        }
        D.setFromTriplets(diag.begin(), diag.end());
        const Eigen::SparseMatrix<double> K(block(K_, p));
        const Eigen::SparseMatrix<double> Kt(K.transpose());
        Eigen::SparseMatrix<double> A((0.5*cK)*(K + Kt) + D);
        A.makeCompressed();

        ldlt_[p].reset(new Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>());
        ldlt_[p]->compute(A);
        if (ldlt_[p]->info() == Eigen::Success)
        {
            continue;
        }
        ldlt_[p].reset();
        Eigen::SparseMatrix<double> B(cK*K + D);
        B.makeCompressed();
        lu_[p].reset(new Eigen::SparseLU<Eigen::SparseMatrix<double>>());
        lu_[p]->analyzePattern(B);
        lu_[p]->factorize(B);
        if (lu_[p]->info() != Eigen::Success)
        {
            singular[p] = 1;
            message[p] = lu_[p]->lastErrorMessage();
        }
    }

    forAll(singular, p)
    {
        if (singular[p])
        {
            FatalErrorInFunction
                << "The structure's implicit step matrix (" << nDof_
                << " unknowns, its part " << p << " of " << nParts << ": "
                << 3*parts_[p].size() << ") is singular: "
                << message[p].c_str() << exit(FatalError);
        }
    }
}


void Foam::structureTangent::solve
(
    const UList<vector2D>& rForce,
    const UList<scalar>& rTorque,
    List<vector2D>& du,
    scalarList& dtheta
) const
{
    du.setSize(X_.size());
    dtheta.setSize(X_.size());
    forAll(X_, i)
    {
        if (dof_[i] < 0)
        {
            du[i] = Zero;
            dtheta[i] = 0;
        }
    }

    // Each part on a thread
    #pragma omp parallel for schedule(dynamic, 1)
    for (label p = 0; p < label(parts_.size()); ++p)
    {
        const labelList& part = parts_[p];
        Eigen::VectorXd b(3*part.size());
        forAll(part, k)
        {
            const label i = part[k];
            b(3*k) = rForce[i].x();
            b(3*k + 1) = rForce[i].y();
            b(3*k + 2) = rTorque[i];
        }
        const Eigen::VectorXd s
        (
            ldlt_[p] ? Eigen::VectorXd(ldlt_[p]->solve(b))
          : Eigen::VectorXd(lu_[p]->solve(b))
        );
        forAll(part, k)
        {
            const label i = part[k];
            du[i] = vector2D(s(3*k), s(3*k + 1));
            dtheta[i] = s(3*k + 2);
        }
    }
}


// ************************************************************************* //
