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

#include "mpsCloudOutput.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsCloudOutput::mpsCloudOutput(const polyMesh& mesh)
:
    lagrangian_(mesh),
    vtk_(mesh.time())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mpsCloudOutput::addSource
(
    const word& cloudName,
    const cloudFieldSource& source
)
{
    sources_.append(std::make_pair(cloudName, &source));
}


void Foam::mpsCloudOutput::write(const mpsCloud& cloud)
{
    cloudFields clouds[] =
    {
        cloudFields("fluid", cloud, {particleKind::fluid}),
        cloudFields("wall", cloud, {particleKind::wall, particleKind::dummy}),
        cloudFields("structure", cloud, {particleKind::structure})
    };

    for (cloudFields& c : clouds)
    {
        if (!c.size())
        {
            continue;
        }
        for (const auto& source : sources_)
        {
            if (source.first == c.name())
            {
                source.second->addFields(c.ids(), c);
            }
        }
        lagrangian_.write(c);
        vtk_.write(c);
    }
}


// ************************************************************************* //
