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
#include "mpsStructure.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpsCloudOutput::mpsCloudOutput(const polyMesh& mesh)
:
    lagrangian_(mesh),
    vtk_(mesh.time())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::mpsCloudOutput::write
(
    const mpsCloud& cloud,
    const mpsStructure* structure
)
{
    cloudFields clouds[] =
    {
        cloudFields("fluid", cloud, {particleKind::fluid}),
        cloudFields("wall", cloud, {particleKind::wall, particleKind::dummy}),
        cloudFields("structure", cloud, {particleKind::structure})
    };

    if (structure)
    {
        structure->addFields(clouds[2]);
    }

    for (const cloudFields& c : clouds)
    {
        if (c.size())
        {
            lagrangian_.write(c);
            vtk_.write(c);
        }
    }
}


// ************************************************************************* //
