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

#include "spaceTimeTable.H"
#include "error.H"
#include "DynamicList.H"
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::spaceTimeTable::locate
(
    const scalarList& x,
    const scalar v,
    label& i,
    scalar& w
)
{
    const label n = x.size();
    if (n == 1 || v <= x[0])
    {
        i = 0;
        w = 0;
        return;
    }
    if (v >= x[n - 1])
    {
        i = n - 2;
        w = 1;
        return;
    }
    // Bisection: x[lo] <= v < x[hi]
    label lo = 0, hi = n - 1;
    while (hi - lo > 1)
    {
        const label mid = (lo + hi)/2;
        (x[mid] <= v ? lo : hi) = mid;
    }
    i = lo;
    w = (v - x[lo])/(x[hi] - x[lo]);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::spaceTimeTable::spaceTimeTable
(
    const fileName& file,
    const dictionary& dict
)
:
    file_(file),
    s_(),
    t_(),
    values_()
{
    std::ifstream is(file_.c_str());
    if (!is.good())
    {
        FatalIOErrorInFunction(dict)
            << "Cannot read the table " << file_ << exit(FatalIOError);
    }

    auto fail = [&](const label lineNo, const std::string& why)
    {
        FatalIOErrorInFunction(dict)
            << "Table " << file_ << ", line " << lineNo << ": " << why.c_str()
            << ". Valid: a line 's s_1 s_2 ...' (increasing positions [m]),"
            << " then lines 't p_1 p_2 ...' (increasing times [s], one value"
            << " per position); # starts a comment" << exit(FatalIOError);
    };

    std::string line;
    label lineNo = 0;
    DynamicList<scalar> t;
    DynamicList<scalarList> values;
    while (std::getline(is, line))
    {
        ++lineNo;
        const auto hash = line.find('#');
        if (hash != std::string::npos)
        {
            line.erase(hash);
        }
        std::istringstream ls(line);
        std::string first;
        if (!(ls >> first))
        {
            continue;
        }
        DynamicList<scalar> row;
        double v;
        while (ls >> v)
        {
            if (!std::isfinite(v))
            {
                fail(lineNo, "a value is not finite");
            }
            row.append(v);
        }
        if (!ls.eof())
        {
            fail(lineNo, "a value is not a number");
        }
        if (s_.empty())
        {
            if (first != "s" || row.empty())
            {
                fail(lineNo, "the first line must be 's' and the positions");
            }
            s_ = row;
            for (label k = 1; k < s_.size(); ++k)
            {
                if (!(s_[k] > s_[k - 1]))
                {
                    fail(lineNo, "the positions must increase");
                }
            }
            continue;
        }
        std::istringstream ts(first);
        double ti;
        if (!(ts >> ti) || !ts.eof() || !std::isfinite(ti))
        {
            fail(lineNo, "a row must start with its time");
        }
        if (row.size() != s_.size())
        {
            fail
            (
                lineNo,
                "a row holds " + std::to_string(row.size())
              + " values for " + std::to_string(s_.size()) + " positions"
            );
        }
        if (t.size() && !(ti > t.last()))
        {
            fail(lineNo, "the times must increase");
        }
        t.append(ti);
        values.append(scalarList(row));
    }
    if (s_.empty() || t.empty())
    {
        fail(lineNo, "no positions, or no time");
    }
    t_.transfer(t);
    values_.transfer(values);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::spaceTimeTable::value(const scalar s, const scalar t) const
{
    label i, j;
    scalar ws, wt;
    locate(s_, s, i, ws);
    locate(t_, t, j, wt);
    auto at = [&](const label row)
    {
        const scalarList& v = values_[row];
        return s_.size() == 1 ? v[0] : (1 - ws)*v[i] + ws*v[i + 1];
    };
    return t_.size() == 1 ? at(0) : (1 - wt)*at(j) + wt*at(j + 1);
}


// ************************************************************************* //
