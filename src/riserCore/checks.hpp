// riserCore: argument checks shared by every law of the physics core.
//
// A law called with a non-physical argument throws std::invalid_argument
// whose message names the law, the argument, its value and the allowed range,
// so that callers (the OpenFOAM submodels, the mesh-free driver) can turn it
// into a message naming the dictionary entry.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CHECKS_HPP
#define RISERCORE_CHECKS_HPP

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace riser {

// Kinds of interval an argument may be required to lie in.
enum class Bound { open, closed };

//- The exception of requireInRange, kept out of line: the laws check their
//  arguments at every call, and the check itself is two comparisons
[[noreturn]] __attribute__((noinline, cold))
inline void throwOutOfRange(const char* law, const char* name, double value,
                            double lo, Bound loKind, double hi, Bound hiKind)
{
    std::ostringstream msg;
    msg << law << ": argument '" << name << "' = " << value
        << " outside the allowed range " << (loKind == Bound::closed ? '[' : '(')
        << lo << ", " << hi << (hiKind == Bound::closed ? ']' : ')');
    throw std::invalid_argument(msg.str());
}

//- Throw unless lo (<|<=) value (<|<=) hi; NaN is always rejected.
inline void requireInRange(const char* law, const char* name, double value,
                           double lo, Bound loKind, double hi, Bound hiKind)
{
    const bool okLo = loKind == Bound::closed ? value >= lo : value > lo;
    const bool okHi = hiKind == Bound::closed ? value <= hi : value < hi;
    if (__builtin_expect(okLo && okHi, 1)) return;
    throwOutOfRange(law, name, value, lo, loKind, hi, hiKind);
}

//- Throw unless value > 0 (and finite).
inline void requirePositive(const char* law, const char* name, double value)
{
    requireInRange(law, name, value, 0.0, Bound::open, HUGE_VAL, Bound::open);
}

//- Throw unless value >= 0 (and finite).
inline void requireNonNegative(const char* law, const char* name, double value)
{
    requireInRange(law, name, value, 0.0, Bound::closed, HUGE_VAL, Bound::open);
}

} // namespace riser

#endif
