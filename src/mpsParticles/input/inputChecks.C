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

#include "inputChecks.H"
#include <string>
#include "DynamicList.H"
#include <cctype>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Levenshtein distance, letter case ignored
Foam::label editDistance(const std::string& a, const std::string& b)
{
    const std::size_t n = a.size(), m = b.size();
    std::vector<Foam::label> prev(m + 1), cur(m + 1);
    for (std::size_t j = 0; j <= m; ++j)
    {
        prev[j] = j;
    }
    for (std::size_t i = 1; i <= n; ++i)
    {
        cur[0] = i;
        for (std::size_t j = 1; j <= m; ++j)
        {
            const bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
            cur[j] = std::min
            (
                std::min(prev[j] + 1, cur[j - 1] + 1),
                prev[j - 1] + (same ? 0 : 1)
            );
        }
        std::swap(prev, cur);
    }
    return prev[m];
}

// Words separated by spaces
std::string words(const Foam::UList<Foam::word>& list)
{
    std::string s;
    for (const Foam::word& w : list)
    {
        s += (s.empty() ? "" : " ") + w;
    }
    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::word Foam::inputChecks::nearest(const word& key, const wordList& valid)
{
    word best;
    label bestDistance = max(label(1), label(key.size()/2)) + 1;
    for (const word& v : valid)
    {
        const label d = editDistance(key, v);
        if (d < bestDistance)
        {
            bestDistance = d;
            best = v;
        }
    }
    return best;
}


void Foam::inputChecks::keywords
(
    const dictionary& dict,
    const wordList& valid,
    const string& what
)
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (key == "FoamFile" || valid.found(key))
        {
            continue;
        }
        const word near(nearest(key, valid));
        FatalIOErrorInFunction(dict)
            << "Unknown entry '" << key << "'";
        if (what.size())
        {
            FatalIOError<< " in " << what.c_str();
        }
        if (near.size())
        {
            FatalIOError<< " (did you mean '" << near << "'?)";
        }
        FatalIOError
            << nl << "Valid entries: " << words(valid).c_str()
            << exit(FatalIOError);
    }
}


const Foam::dictionary& Foam::inputChecks::subDict
(
    const dictionary& dict,
    const word& key
)
{
    const dictionary* d = optionalDict(dict, key);
    if (!d)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' (a dictionary { ... }) is missing"
            << exit(FatalIOError);
    }
    return *d;
}


const Foam::dictionary* Foam::inputChecks::optionalDict
(
    const dictionary& dict,
    const word& key
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        return nullptr;
    }
    if (!e->isDict())
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be a dictionary { ... }, got '"
            << e->stream().toString().c_str() << "'" << exit(FatalIOError);
    }
    return &e->dict();
}


const Foam::dictionary& Foam::inputChecks::value
(
    const dictionary& dict,
    const word& key
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (e && e->isDict())
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be a value, not a dictionary"
            << " { ... }" << exit(FatalIOError);
    }
    return dict;
}


const Foam::dictionary& Foam::inputChecks::values
(
    const dictionary& dict,
    const wordList& keys
)
{
    for (const word& key : keys)
    {
        value(dict, key);
    }
    return dict;
}


Foam::wordList Foam::inputChecks::functionObjectKeywords
(
    std::initializer_list<word> own
)
{
    wordList keys
    ({
        "type", "libs", "region", "enabled", "log", "timeStart", "timeEnd",
        "executeControl", "executeInterval", "writeControl",
        "writeInterval", "writePrecision", "writeToFile", "useUserTime"
    });
    for (const word& w : own)
    {
        keys.append(w);
    }
    return keys;
}


void Foam::inputChecks::exclusive
(
    const dictionary& dict,
    const wordList& keys
)
{
    DynamicList<word> given;
    for (const word& key : keys)
    {
        if (dict.found(key, keyType::LITERAL))
        {
            given.append(key);
        }
    }
    if (given.size() > 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entries " << words(given).c_str() << " say the same thing"
            << " in two ways: give one of " << words(keys).c_str()
            << exit(FatalIOError);
    }
}


void Foam::inputChecks::checkRange
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const char* range
)
{
    // The range's form: one bound ("> 0", ">= 1", "< 90", "<= 1") or an
    // interval ("(0, 1]")
    const std::string r(range);
    bool ok = false;
    bool parsed = false;
    std::string what;
    if (r.size() > 2 && (r[0] == '>' || r[0] == '<'))
    {
        const bool orEqual = r[1] == '=';
        const scalar bound = std::stod(r.substr(orEqual ? 2 : 1));
        ok = r[0] == '>'
            ? (orEqual ? value >= bound : value > bound)
            : (orEqual ? value <= bound : value < bound);
        what = r == "> 0" ? std::string("must be positive (> 0)") : "must be " + r;
        parsed = true;
    }
    else if
    (
        r.size() > 4
     && (r.front() == '(' || r.front() == '[')
     && (r.back() == ')' || r.back() == ']')
     && r.find(',') != std::string::npos
    )
    {
        const std::size_t comma = r.find(',');
        const scalar a = std::stod(r.substr(1, comma - 1));
        const scalar b = std::stod(r.substr(comma + 1, r.size() - comma - 2));
        ok =
            (r.front() == '(' ? value > a : value >= a)
         && (r.back() == ')' ? value < b : value <= b);
        what = "must lie in " + r;
        parsed = true;
    }
    if (!parsed)
    {
        FatalErrorInFunction
            << "The range '" << r << "' of entry '" << key
            << "' is not one inputChecks::checkRange reads" << exit(FatalError);
    }
    if (!ok)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' " << what.c_str() << ", got " << value
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
