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

#include "particleProbes.H"
#include "inputChecks.H"
#include "mpsState.H"
#include "mpsDecomposition.H"
#include "writeChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(particleProbes, 0);
    addToRunTimeSelectionTable(functionObject, particleProbes, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::particleProbes::writeFileHeader(const label fi)
{
    const word& fieldName = fields_[fi];
    OFstream& os = files(fi);
    writeHeader(os, "Particle probes: " + fieldName);
    forAll(locations_, i)
    {
        writeCommented(os, "Probe " + Foam::name(i));
        os  << ' ' << locations_[i] << nl;
    }
    writeCommented(os, "Time");
    forAll(locations_, i)
    {
        const word col("probe" + Foam::name(i));
        if (fieldName == "U")
        {
            writeTabbed(os, col + "_x");
            writeTabbed(os, col + "_y");
        }
        else
        {
            writeTabbed(os, col);
        }
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::particleProbes::particleProbes
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    logFiles(mesh_, name),
    locations_(),
    fields_({"p", "U"}),
    radius_(2.1),
    kernelDict_(),
    kernel_()
{
    read(dict);
    resetNames(fields_);
    if (Pstream::master())
    {
        forAll(fields_, fi)
        {
            writeFileHeader(fi);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::particleProbes::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    inputChecks::keywords
    (
        dict,
        inputChecks::functionObjectKeywords
        (
            {"probeLocations", "fields", "radius", "kernel"}
        ),
        "function object " + name()
    );
    logFiles::read(dict);

    locations_ = dict.get<pointField>("probeLocations");
    const boundBox& domain = mesh_.bounds();
    for (const point& p : locations_)
    {
        if
        (
            p.x() < domain.min().x() || p.x() > domain.max().x()
         || p.y() < domain.min().y() || p.y() > domain.max().y()
        )
        {
            FatalIOErrorInFunction(dict)
                << "Probe location " << p << " of 'probeLocations' is"
                << " outside the domain (the background mesh, "
                << domain.min() << " to " << domain.max() << ")"
                << exit(FatalIOError);
        }
    }
    fields_ = dict.getOrDefault<wordList>("fields", wordList({"p", "U"}));
    for (const word& f : fields_)
    {
        if (f != "p" && f != "U")
        {
            FatalIOErrorInFunction(dict)
                << "Unknown field " << f << " in 'fields'; valid: p U"
                << exit(FatalIOError);
        }
    }
    radius_ = dict.getOrDefault<scalar>("radius", 2.1);
    if (!(radius_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'radius' (in l0) must be positive, got " << radius_
            << exit(FatalIOError);
    }
    // The kernel sub-dictionary, of type polynomial unless it says
    dictionary kernel(dict.subOrEmptyDict("kernel"));
    if (!kernel.found("type"))
    {
        kernel.add("type", word("polynomial"));
    }
    kernelDict_.clear();
    kernelDict_.add("kernel", kernel);
    // Check the kernel name now, with the list of valid ones; the kernel
    // itself is built at the first write
    mpsKernel::New(kernelDict_, 1);
    kernel_.clear();
    return true;
}


bool Foam::functionObjects::particleProbes::execute()
{
    return true;
}


bool Foam::functionObjects::particleProbes::write()
{
    const mpsState& state = mpsState::lookup(mesh_);
    const mpsCloud& cloud = state.cloud();
    if (!kernel_)
    {
        kernel_ = mpsKernel::New(kernelDict_, radius_*state.fluid().l0());
    }
    const mpsKernel& kernel = kernel_();
    const scalar re = kernel.re();

    const label nProbes = locations_.size();
    scalarField p(nProbes, Zero);
    List<vector2D> U(nProbes, Zero);
    scalarField sumW(nProbes, Zero);

    // Probes are few: a direct pass over the particles is cheapest
    const UList<vector2D>& x = cloud.x();
    const UList<particleKind>& kind = cloud.kind();
    forAll(x, j)
    {
        // (under -parallel each particle once: the halos are another
        // rank's, the replicated structure the master's)
        if
        (
            kind[j] == particleKind::dummy
         || cloud.halo()[j]
         || (mpsDecomposition::replicated(kind[j]) && !Pstream::master())
        )
        {
            continue;
        }
        forAll(locations_, i)
        {
            const vector2D d
            (
                x[j].x() - locations_[i].x(),
                x[j].y() - locations_[i].y()
            );
            if (magSqr(d) < re*re)
            {
                const scalar w = kernel.w(mag(d));
                sumW[i] += w;
                p[i] += w*cloud.p()[j];
                U[i] += w*cloud.U()[j];
            }
        }
    }
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(sumW, plusEqOp<scalar>());
        Pstream::listCombineGather(p, plusEqOp<scalar>());
        Pstream::listCombineGather(U, plusEqOp<vector2D>());
    }
    forAll(sumW, i)
    {
        if (sumW[i] > 0)
        {
            p[i] /= sumW[i];
            U[i] /= sumW[i];
        }
    }

    if (Pstream::master())
    {
        forAll(fields_, fi)
        {
            const fileName failed
            (
                writeChecks::writes
                (
                    [&]()
                    {
                        OFstream& os = files(fi);
                        writeCurrentTime(os);
                        forAll(locations_, i)
                        {
                            if (fields_[fi] == "U")
                            {
                                os  << tab << U[i].x() << tab << U[i].y();
                            }
                            else
                            {
                                os  << tab << p[i];
                            }
                        }
                        os  << endl;
                        return
                            writeChecks::flushed(os) ? fileName() : os.name();
                    }
                )
            );
            if (!failed.empty())
            {
                writeChecks::stopSeries(failed, time_);
            }
        }
    }
    return true;
}


// ************************************************************************* //
