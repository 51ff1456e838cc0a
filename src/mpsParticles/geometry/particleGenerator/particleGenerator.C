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

#include "particleGenerator.H"
#include "inputChecks.H"
#include <fstream>
#include "particleShape.H"
#include "neighbourList.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::particleGenerator::boundaryOverStructure
(
    const particleKind a,
    const particleKind b
)
{
    const auto boundary = [](const particleKind k)
    {
        return k == particleKind::wall || k == particleKind::dummy;
    };
    return
        (a == particleKind::structure && boundary(b))
     || (b == particleKind::structure && boundary(a));
}


void Foam::particleGenerator::checkOverlaps(mpsCloud& cloud) const
{
    const label n = cloud.size();
    if (n == 0)
    {
        return;
    }

    const UList<scalar>& spacing = cloud.spacing();
    const UList<label>& region = cloud.region();
    const UList<particleKind>& kind = cloud.kind();
    const scalar maxSpacing = max(scalarField(spacing));

    const neighbourList nbrs(cloud.x(), 0.5*maxSpacing);
    const dictionary& regionsDict = dict_.subDict("regions");

    List<bool> keep(n, true);
    labelList nDropped(cloud.regionNames().size(), Zero);

    // In the order of generation (the ids): of two coinciding particles
    // of one kind or region, the later is dropped
    const UList<label>& id = cloud.id();
    labelList byId(n);
    forAll(id, i)
    {
        byId[id[i]] = i;
    }
    for (const label i : byId)
    {
        if (!keep[i])
        {
            continue;
        }
        for (const label j : nbrs[i])
        {
            if (id[j] < id[i] || !keep[j])
            {
                continue;
            }
            const scalar d = mag(cloud.x()[j] - cloud.x()[i]);
            if (d >= 0.5*min(spacing[i], spacing[j]))
            {
                continue;
            }
            if (boundaryOverStructure(kind[i], kind[j]))
            {
                continue;
            }
            if (kind[i] == kind[j] || region[i] == region[j])
            {
                keep[j] = false;
                ++nDropped[region[j]];
            }
            else
            {
                const word& ri = cloud.regionNames()[region[i]];
                const word& rj = cloud.regionNames()[region[j]];
                FatalIOErrorInFunction(regionsDict.subDict(rj))
                    << "Regions '" << ri << "' ("
                    << particleKindNames[kind[i]] << ") and '" << rj
                    << "' (" << particleKindNames[kind[j]]
                    << ") overlap near " << cloud.x()[i] << ": particles "
                    << d << " apart, closer than half their spacing."
                    << nl << "Regions of different kinds must not overlap."
                    << exit(FatalIOError);
            }
        }
    }

    forAll(nDropped, regioni)
    {
        if (nDropped[regioni])
        {
            Info<< "    region " << cloud.regionNames()[regioni]
                << ": dropped " << nDropped[regioni]
                << " particles coinciding with earlier ones" << nl;
        }
    }

    cloud.subset(keep);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleGenerator::particleGenerator
(
    const dictionary& particleDict,
    const scalar fluidSpacing,
    const scalar structureSpacing,
    const scalar wallSupport
)
:
    dict_(particleDict),
    fluidSpacing_(fluidSpacing),
    structureSpacing_(structureSpacing),
    wallSupport_(wallSupport)
{}


Foam::scalar Foam::particleGenerator::regionSpacing
(
    const word& name,
    const dictionary& rDict
) const
{
    inputChecks::values(rDict, {"type", "kind", "spacing", "dummyLayers"});
    const word kindName(rDict.get<word>("kind"));
    if (!particleKindNames.found(kindName))
    {
        FatalIOErrorInFunction(rDict)
            << "Entry 'kind' of region " << name << " is " << kindName
            << "; valid kinds: " << flatOutput(particleKindNames.names())
            << exit(FatalIOError);
    }
    const scalar spacing = rDict.getOrDefault<scalar>
    (
        "spacing",
        particleKindNames[kindName] == particleKind::structure
      ? structureSpacing_
      : fluidSpacing_
    );
    if (!(spacing > 0))
    {
        FatalIOErrorInFunction(rDict)
            << "Entry 'spacing' of region " << name
            << " must be positive, got " << spacing << exit(FatalIOError);
    }
    return spacing;
}


void Foam::particleGenerator::checkSize(const dictionary& regionsDict) const
{
    // Each particle costs about bytesPerParticle in a run (the cloud's
    // fields, two neighbour lists with their weights, the PPE matrix
    // row): 1.3-1.4 kB measured (growth of the maximum resident set with
    // the particles, rigid wedge at l0 = 10, 5, 2.5 mm: 11k, 43k, 164k
    // particles), taken as 2 kB
    const scalar bytesPerParticle = 2048;

    scalar n = 0;
    for (const entry& e : regionsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(regionsDict)
                << "Entry '" << e.keyword() << "' in 'regions' is not a"
                << " dictionary: each region is { type ...; kind ...; }"
                << exit(FatalIOError);
        }
        const scalar spacing = regionSpacing(e.keyword(), e.dict());
        n += particleShape::New(e.dict())->estimatedCount(spacing);
    }

    const bool limited = dict_.found("maxParticles");
    const scalar maxParticles =
        limited ? dict_.get<scalar>("maxParticles") : GREAT;
    const scalar available = availableMemory();
    if ((limited && n > maxParticles) || n*bytesPerParticle > available)
    {
        // (the counts as reals: a spacing far too small makes more
        // particles than a label holds)
        FatalIOErrorInFunction(regionsDict)
            << "The regions would make about " << n << " particles";
        if (limited && n > maxParticles)
        {
            FatalIOError << ", more than maxParticles " << maxParticles;
        }
        else
        {
            FatalIOError
                << ", about " << n*bytesPerParticle/1073741824.0
                << " GiB to run, more than the "
                << available/1073741824.0 << " GiB of memory available";
        }
        FatalIOError
            << ". Is a spacing too small? The fluid's l0 is " << fluidSpacing_
            << " m (constant/mpsProperties), the structure's spacing "
            << structureSpacing_ << " m; a region's own 'spacing' takes"
            << " their place" << exit(FatalIOError);
    }
}


Foam::scalar Foam::particleGenerator::availableMemory()
{
    // MemAvailable of /proc/meminfo [kB]; unlimited if it cannot be read
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    scalar kB = 0;
    std::string unit;
    while (meminfo >> key >> kB >> unit)
    {
        if (key == "MemAvailable:")
        {
            return 1024*kB;
        }
    }
    return GREAT;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleGenerator::generate
(
    mpsCloud& cloud,
    const boundBox& domain
) const
{
    cloud.clear();

    const dictionary& regionsDict = inputChecks::subDict(dict_, "regions");
    if (regionsDict.empty())
    {
        FatalIOErrorInFunction(regionsDict)
            << "No regions: add one sub-dictionary per region of particles"
            << exit(FatalIOError);
    }

    checkSize(regionsDict);

    const scalar tol = 1e-9*mag(domain.span());

    for (const entry& e : regionsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(regionsDict)
                << "Entry '" << e.keyword() << "' in 'regions' is not a"
                << " dictionary: each region is { type ...; kind ...; }"
                << exit(FatalIOError);
        }
        const word& name = e.keyword();
        const dictionary& rDict = e.dict();

        const scalar spacing = regionSpacing(name, rDict);
        const particleKind kind = particleKindNames[rDict.get<word>("kind")];

        autoPtr<particleShape> shape(particleShape::New(rDict));

        const label nLayers = shape->nLayers(spacing);
        if (rDict.found("thickness"))
        {
            // A whole number of rows: say so where it is not the thickness
            // asked (a panel's bending stiffness goes as its cube)
            const scalar asked = rDict.get<scalar>("thickness");
            const scalar made = nLayers*spacing;
            if (mag(made - asked) > 0.01*asked)
            {
                IOWarningInFunction(rDict)
                    << "Region " << name << ": 'thickness' " << asked
                    << " m at the spacing " << spacing << " m makes "
                    << nLayers << " rows, " << made << " m thick ("
                    << 100*(made/asked - 1) << "%: bending stiffness x "
                    << pow3(made/asked) << "). For the thickness asked, a"
                    << " spacing of thickness/n (n rows)" << endl;
            }
        }
        label dummyLayers = 0;
        if (rDict.found("dummyLayers"))
        {
            dummyLayers = rDict.get<label>("dummyLayers");
            if (kind != particleKind::wall)
            {
                FatalIOErrorInFunction(rDict)
                    << "Entry 'dummyLayers' is for wall regions; region "
                    << name << " is " << particleKindNames[kind]
                    << exit(FatalIOError);
            }
            if (dummyLayers < 0 || dummyLayers >= nLayers)
            {
                FatalIOErrorInFunction(rDict)
                    << "Entry 'dummyLayers' of region " << name << " is "
                    << dummyLayers << "; valid: 0 to " << nLayers - 1
                    << " (the region has " << nLayers << " layers)"
                    << exit(FatalIOError);
            }
            // The dummies at 1, 2, ... spacings behind the wall layer must
            // hold every layer closer than the number-density radius (the
            // kernels vanish at re)
            const label needed = label(std::floor(wallSupport_/spacing - 1e-6));
            if (dummyLayers > 0 && dummyLayers < needed)
            {
                FatalIOErrorInFunction(rDict)
                    << "Entry 'dummyLayers' of region " << name << " is "
                    << dummyLayers << "; valid: " << needed << " or more"
                    << " (and 'layers' at least " << needed + 1 << ")."
                    << nl << "The number-density kernel's radius "
                    << wallSupport_/spacing << " spacings (re.numberDensity"
                    << " of constant/mpsProperties) reaches " << needed
                    << " layers behind the wall layer: with fewer dummies"
                    << " its wall particles' number density is short (and"
                    << " the number-density wall test, wallBeta, sets them"
                    << " to p = 0)."
                    << exit(FatalIOError);
            }
        }

        DynamicList<vector2D> points;
        DynamicList<label> layers;
        shape->generate(spacing, points, layers);

        if (points.empty())
        {
            FatalIOErrorInFunction(rDict)
                << "Region " << name << " has no particles: is the shape"
                << " smaller than the spacing " << spacing << '?'
                << exit(FatalIOError);
        }

        const label regioni = cloud.addRegion(name);
        const label firstDummyLayer = nLayers - dummyLayers;

        List<particleKind> kinds(points.size());
        forAll(points, i)
        {
            const vector2D& p = points[i];
            if
            (
                p.x() < domain.min().x() - tol
             || p.x() > domain.max().x() + tol
             || p.y() < domain.min().y() - tol
             || p.y() > domain.max().y() + tol
            )
            {
                FatalIOErrorInFunction(rDict)
                    << "Region " << name << " has particles outside the"
                    << " domain, the first at " << p << "." << nl
                    << "The domain is the background mesh (blockMesh) from "
                    << domain.min() << " to " << domain.max()
                    << "; it must hold every particle, dummies included."
                    << exit(FatalIOError);
            }

            kinds[i] =
                (layers[i] >= firstDummyLayer && dummyLayers > 0)
              ? particleKind::dummy
              : kind;
        }
        cloud.append(points, kinds, regioni, spacing);
    }

    checkOverlaps(cloud);
}


// ************************************************************************* //
