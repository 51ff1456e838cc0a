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

#include "couplingScheme.H"
#include "inputChecks.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::word Foam::couplingScheme::selectedType
(
    const dictionary& structureProperties
)
{
    const dictionary* couplingPtr = structureProperties.findDict("coupling");
    if (!couplingPtr)
    {
        return "none";
    }
    const word schemeType
    (
        couplingPtr->getOrDefault<word>("scheme", "explicit")
    );
    // none is the scheme of a case without a coupling dictionary: in one,
    // the structure would move and the walls it names stay where they are
    if (schemeType == "none" || !dictionaryConstructorTablePtr_->found(schemeType))
    {
        DynamicList<word> valid;
        for (const word& w : dictionaryConstructorTablePtr_->sortedToc())
        {
            if (w != "none")
            {
                valid.append(w);
            }
        }
        FatalIOErrorInFunction(*couplingPtr)
            << "Entry 'scheme': " << schemeType << " is not valid"
            << (
                   schemeType == "none"
                 ? " in a coupling dictionary (its walls would stay where"
                   " they are while the structure moves; to run without"
                   " coupling, remove the dictionary coupling)"
                 : ""
               ) << nl
            << "Valid coupling schemes: " << valid
            << exit(FatalIOError);
    }
    return schemeType;
}


Foam::autoPtr<Foam::couplingScheme> Foam::couplingScheme::New
(
    const dictionary& structureProperties,
    mpsFluid& fluid,
    mpsStructure& structure,
    fluidStructureInterface& interface
)
{
    const word schemeType(selectedType(structureProperties));
    const dictionary* couplingPtr = structureProperties.findDict("coupling");
    const dictionary& dict = couplingPtr ? *couplingPtr : dictionary::null;

    autoPtr<couplingScheme> scheme
    (
        dictionaryConstructorTablePtr_->cfind(schemeType)()
        (
            dict, fluid, structure, interface
        )
    );

    if (couplingPtr)
    {
        wordList valid(fluidStructureInterface::entries());
        valid.append("scheme");
        valid.append(scheme->entries());
        inputChecks::keywords(dict, valid, "coupling");
    }

    if (interface.active())
    {
        Info<< "Coupling scheme " << schemeType << nl << endl;
    }

    return scheme;
}


// ************************************************************************* //
