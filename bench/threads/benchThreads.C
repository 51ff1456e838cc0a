/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | mpsFsiFoam: MPS hydroelastic slamming
   \\    /   O peration     | built on OpenFOAM v1912
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    benchThreads

Description
    What a cache line costs between two cores, which decides how the
    fluid step shares its rows between threads (rowChunks): the round trip
    of a flag between two threads pinned to cores 0 and 1 (tens of ns on
    one die, hundreds between dies), and a pass over an 8 MB array (the
    fluid step's pair weights of Case 2) after the same thread wrote it
    and after the other did.

\*---------------------------------------------------------------------------*/

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>
#include <pthread.h>
#include <sched.h>

namespace
{

void pin(const int core)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(core, &set);
    pthread_setaffinity_np(pthread_self(), sizeof(set), &set);
}

double seconds(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}

} // End anonymous namespace


int main()
{
    if (std::thread::hardware_concurrency() < 2)
    {
        std::printf("benchThreads: one core, nothing to measure\n");
        return 0;
    }

    // A flag passed back and forth: each pass moves its line to the other
    // core
    {
        const long n = 200000;
        double best = 1e9;
        for (int rep = 0; rep < 3; ++rep)
        {
            std::atomic<long> flag{0};
            std::thread other
            (
                [&]
                {
                    pin(1);
                    for (long i = 0; i < n; ++i)
                    {
                        while (flag.load(std::memory_order_acquire) != 2*i + 1) {}
                        flag.store(2*i + 2, std::memory_order_release);
                    }
                }
            );
            pin(0);
            const auto t0 = std::chrono::steady_clock::now();
            for (long i = 0; i < n; ++i)
            {
                flag.store(2*i + 1, std::memory_order_release);
                while (flag.load(std::memory_order_acquire) != 2*i + 2) {}
            }
            best = std::min(best, seconds(t0)/n);
            other.join();
        }
        std::printf("cache line round trip between cores 0 and 1: %.0f ns\n", 1e9*best);
    }

    // An 8 MB array read and written after this core or the other wrote it
    {
        const long n = 1 << 20;
        std::vector<double> a(n, 1.0);
        auto pass = [&a, n](const double f)
        {
            for (long i = 0; i < n; ++i)
            {
                a[i] = a[i]*f + 1e-9;
            }
        };
        for (const int writer : {0, 1})
        {
            double best = 1e9;
            for (int rep = 0; rep < 20; ++rep)
            {
                std::thread w([&] { pin(writer); pass(1.0000001); });
                w.join();
                pin(0);
                const auto t0 = std::chrono::steady_clock::now();
                pass(0.9999999);
                best = std::min(best, seconds(t0));
            }
            std::printf
            (
                "8 MB pass on core 0 after core %d wrote it: %.2f ms\n",
                writer, 1e3*best
            );
        }
    }
    return 0;
}
