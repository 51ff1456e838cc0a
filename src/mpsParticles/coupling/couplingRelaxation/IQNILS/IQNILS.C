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

#include "IQNILS.H"
#include "addToRunTimeSelectionTable.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace couplingRelaxations
{
    defineTypeNameAndDebug(IQNILS, 0);
    addToRunTimeSelectionTable(couplingRelaxation, IQNILS, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingRelaxations::IQNILS::IQNILS(const dictionary& dict)
:
    couplingRelaxation(dict),
    reuse_(inputChecks::number<label>(dict, "reuse", 0, ">= 0")),
    current_(),
    history_(),
    rOld_(),
    xTildeOld_(),
    first_(true)
{
    inputChecks::keywords
    (
        dict, {"type", "initial", "reuse"}, "relaxation IQN-ILS"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::couplingRelaxations::IQNILS::info(Ostream& os) const
{
    os  << type() << " (initial " << initial_ << ", reuse " << reuse_ << ")";
}


void Foam::couplingRelaxations::IQNILS::beginStep()
{
    current_ = columns();
    first_ = true;
}


void Foam::couplingRelaxations::IQNILS::update
(
    UList<vector2D>& x,
    const UList<vector2D>& r
)
{
    const label m = 2*x.size();
    Eigen::VectorXd rk(m), xTilde(m);
    forAll(x, k)
    {
        for (direction d = 0; d < 2; ++d)
        {
            rk(2*k + d) = r[k][d];
            xTilde(2*k + d) = x[k][d] + r[k][d];
        }
    }
    if (!first_)
    {
        current_.V.insert(current_.V.begin(), rk - rOld_);
        current_.W.insert(current_.W.begin(), xTilde - xTildeOld_);
    }
    rOld_ = rk;
    xTildeOld_ = xTilde;
    first_ = false;

    // This step's columns, then the earlier steps' that have as many
    // unknowns (the attached particles may change with the ranks'
    // ownership), at most m
    std::vector<const Eigen::VectorXd*> Vc, Wc;
    auto take = [&](const columns& c)
    {
        for (size_t j = 0; j < c.V.size() && label(Vc.size()) < m; ++j)
        {
            if (c.V[j].size() == m)
            {
                Vc.push_back(&c.V[j]);
                Wc.push_back(&c.W[j]);
            }
        }
    };
    take(current_);
    for (const columns& c : history_)
    {
        take(c);
    }

    if (Vc.empty())
    {
        forAll(x, k)
        {
            x[k] += initial_*r[k];
        }
        return;
    }

    const label nc = Vc.size();
    Eigen::MatrixXd V(m, nc), W(m, nc);
    for (label j = 0; j < nc; ++j)
    {
        V.col(j) = *Vc[j];
        W.col(j) = *Wc[j];
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(V);
    qr.setThreshold(1e-10);
    const Eigen::VectorXd alpha(qr.solve(-rk));
    const Eigen::VectorXd next(xTilde + W*alpha);
    forAll(x, k)
    {
        x[k] = vector2D(next(2*k), next(2*k + 1));
    }
}


void Foam::couplingRelaxations::IQNILS::endStep()
{
    if (reuse_ > 0)
    {
        history_.push_front(current_);
        while (label(history_.size()) > reuse_)
        {
            history_.pop_back();
        }
    }
    current_ = columns();
}


// ************************************************************************* //
