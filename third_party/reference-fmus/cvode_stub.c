/* Not part of the Reference FMUs: this project's stand-in for fmusim/FMICVode.c, which needs
   SUNDIALS' CVODE. The project's tests run co-simulation FMUs only (fmusim's model-exchange solver
   is not used), so `--solver cvode` reports that it is not built here. */
#include <stdio.h>

#include "FMICVode.h"

FMISolver* FMICVodeCreate(const FMISolverParameters* solverFunctions) {
    if (solverFunctions && solverFunctions->logError) {
        solverFunctions->logError("fmusim was built without CVODE here: use --solver euler");
    }
    return NULL;
}

void FMICVodeFree(FMISolver* solver) { (void)solver; }

FMISolverStatus FMICVodeStep(FMISolver* solver, double nextTime, double* timeReached, bool* stateEvent) {
    (void)solver; (void)nextTime; (void)timeReached; (void)stateEvent;
    return FMISolverError;
}

FMISolverStatus FMICVodeReset(FMISolver* solver, double time) {
    (void)solver; (void)time;
    return FMISolverError;
}
