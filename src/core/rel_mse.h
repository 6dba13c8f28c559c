// relMSE, the error measure of pbrt, Mitsuba and `veduta diff`: (x − ref)² / (ref² + ε) per
// sample, averaged. Adaptive sampling spends samples by it, so both must use the same ε.
#pragma once

namespace veduta {

// Keeps dark pixels from counting without bound.
inline constexpr double kRelMseEpsilon = 1e-2;

inline double relMseTerm(double value, double reference) {
    double error = value - reference;
    return error * error / (reference * reference + kRelMseEpsilon);
}

}  // namespace veduta
