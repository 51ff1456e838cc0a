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

#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::mpsDecomposition::updateHalos
(
    const mpsCloud& cloud,
    UList<Type>& values
) const
{
    if (!Pstream::parRun() || haloSendIds_.empty())
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(haloSendIds_, proci)
    {
        const labelList& ids = haloSendIds_[proci];
        if (ids.size())
        {
            List<Type> send(ids.size());
            forAll(ids, k)
            {
                send[k] = values[cloud.index(ids[k])];
            }
            UOPstream os(proci, buffers);
            os << send;
        }
    }
    buffers.finishedSends();

    forAll(haloRecvIds_, proci)
    {
        const labelList& ids = haloRecvIds_[proci];
        if (ids.size())
        {
            UIPstream is(proci, buffers);
            const List<Type> received(is);
            forAll(ids, k)
            {
                values[cloud.index(ids[k])] = received[k];
            }
        }
    }
}


// ************************************************************************* //
