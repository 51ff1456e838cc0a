#------------------------------------------------------------------------------
# bench/wedge/summary.awk: the lines bench/wedge prints from a wedge run's
# log.mpsFsiFoam (particles, steps, the split of the solver's time)
#
# Usage: awk -v wall=<s> -v what=<what the wall time includes> \
#            -f summary.awk log.mpsFsiFoam
#------------------------------------------------------------------------------
/^    (fluid|wall|dummy|structure): / { n += $2 }
/^Fluid steps:/ { nSteps = $3 + 0; iters = $NF }
/^Time split/ { gsub(/,/, ""); tn = $5; ta = $8; ts = $11; tr = $13 }
/^Structure sub-steps:/ { gsub(/,/, ""); nSub = $3; tStruct = $5 }
/^Coupling time/ { tCoup = $3 }
/^Structure implicit steps:/ { implicit = $0 }
/^ExecutionTime/ { run = $7 }
END {
    fluid = tn + ta + ts + tr
    printf "wedge Case 2: %d particles, %d fluid steps, %d structural sub-steps\n", n, nSteps, nSub
    printf "wedge Case 2: wall time %.1f s (Allrun, %s; solver %.1f s)\n", wall, what, run
    printf "wedge Case 2: fluid %.1f s (neighbours %.1f, PPE assembly %.1f, PPE solve %.1f, rest %.1f; %s PPE iterations a step), structure %.1f s, coupling %.2f s\n", fluid, tn, ta, ts, tr, iters, tStruct, tCoup
    if (implicit != "") print "wedge Case 2: " implicit
}
#------------------------------------------------------------------------------
