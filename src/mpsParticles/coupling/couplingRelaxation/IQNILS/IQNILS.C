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
    filter_(inputChecks::number<scalar>(dict, "filter", 1e-2, "[0, 1)")),
    current_(),
    history_(),
    rOld_(),
    xTildeOld_(),
    first_(true)
{
    inputChecks::keywords
    (
        dict, {"type", "initial", "reuse", "filter"}, "relaxation IQN-ILS"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::couplingRelaxations::IQNILS::info(Ostream& os) const
{
    os  << type() << " (initial " << initial_ << ", reuse " << reuse_
        << ", filter " << filter_ << ")";
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
    bool restart = false;
    if (!first_)
    {
        current_.V.insert(current_.V.begin(), rk - rOld_);
        current_.W.insert(current_.W.begin(), xTilde - xTildeOld_);
        // An iteration that changed the residual by less than filter of
        // its size brought the model nothing new: the model's own answer
        // would not move the guess (S is not smooth enough there for a
        // secant model, e.g. a contact): the model starts again
        restart = !(current_.V.front().norm() > filter_*rk.norm());
    }
    rOld_ = rk;
    xTildeOld_ = xTilde;
    first_ = false;
    if (restart)
    {
        current_ = columns();
        history_.clear();
        forAll(x, k)
        {
            x[k] += initial_*r[k];
        }
        return;
    }

    // This step's columns, then the earlier steps' that have as many
    // unknowns (the attached particles may change with the ranks'
    // ownership), newest first, filtered (Haelterman et al.'s QR2): by
    // modified Gram-Schmidt, a column whose part orthogonal to the newer
    // ones is below filter times its norm is dropped for good (it would
    // let the solver's noise into alpha)
    // (pointers to the kept columns stay valid: a column is erased only
    // after every column kept before it)
    std::vector<Eigen::VectorXd> Q;
    std::vector<const Eigen::VectorXd*> Vc, Wc;
    auto take = [&](columns& c)
    {
        for (size_t j = 0; j < c.V.size();)
        {
            if (c.V[j].size() != m || label(Q.size()) >= m)
            {
                ++j;
                continue;
            }
            Eigen::VectorXd v(c.V[j]);
            const scalar norm0 = v.norm();
            for (const Eigen::VectorXd& q : Q)
            {
                v -= q.dot(v)*q;
            }
            const scalar normV = v.norm();
            if (!(normV > filter_*norm0))
            {
                c.V.erase(c.V.begin() + j);
                c.W.erase(c.W.begin() + j);
                continue;
            }
            Q.push_back(v/normV);
            Vc.push_back(&c.V[j]);
            Wc.push_back(&c.W[j]);
            ++j;
        }
    };
    take(current_);
    for (columns& c : history_)
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

    // alpha = argmin |V alpha + r^k| over the kept columns (a Householder
    // QR of the few of them)
    const label nc = Vc.size();
    Eigen::MatrixXd V(m, nc), W(m, nc);
    for (label j = 0; j < nc; ++j)
    {
        V.col(j) = *Vc[j];
        W.col(j) = *Wc[j];
    }
    const Eigen::VectorXd alpha(V.householderQr().solve(-rk));
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
