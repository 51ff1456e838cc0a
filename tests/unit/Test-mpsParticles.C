/*---------------------------------------------------------------------------*\
    mpsFsiFoam unit tests (Catch2). Run all, or one test case by name:
        Test-mpsParticles
        Test-mpsParticles "original kernel lattice sums"
    OpenFOAM's fatal errors throw (so a test can expect them).
\*---------------------------------------------------------------------------*/

#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "error.H"

// An OpenFOAM error that a test did not expect: report its message
CATCH_TRANSLATE_EXCEPTION(const Foam::error& err)
{
    return err.message();
}

int main(int argc, char* argv[])
{
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    return Catch::Session().run(argc, argv);
}
