// Errors a user can act on: every message names the file, the place, the key, the bad value and
// what is allowed. Thrown by core and the solvers, printed by the `granlub` command.
#pragma once
#include <stdexcept>
#include <string>

namespace granlub {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& what) : std::runtime_error(what) {}
};

// Bad input in a case file: "<file>:<line>:<col>: [section] key = value: problem (allowed: ...)".
class CaseError : public Error {
public:
    using Error::Error;
};

// A solver that could not produce a result for an operating point (no convergence, crash of an
// external engine, ...). The message says which point, what happened and what to try.
class SolverError : public Error {
public:
    using Error::Error;
};

// A question the solver's model has no answer for (the automaton under a load: it holds a fixed
// number of grains; YADE on the whole ring: it runs the slice only). Not a failure: the sweep
// says so, records it (failure_record.h, kind "no answer") and does not count it as failed.
class NoAnswer : public SolverError {
public:
    using SolverError::SolverError;
};

}  // namespace granlub
