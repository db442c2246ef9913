// Sine and cosine computed by the engine itself, bit for bit the same wherever it is compiled.
//
// The C libraries round sin and cos differently in the last bit (glibc on the command line,
// musl in the WebAssembly module of the browser): a tumbling box's rotations then differ by an
// ulp per substep, and a scene of many contacts (a tower of boxes) grows that into different
// collapses. Every rotation of the engine takes its sine and cosine from here instead, so the
// native and WebAssembly builds give the same numbers (tests/wasm/equal.js), with only +, -, *,
// /, floor and fmod, which IEEE 754 rounds alike everywhere. Accuracy: within 1 ulp of the true
// values for |x| up to 8e5 rad (tested against the C library to 2 ulp); beyond, x is first
// reduced by fmod(x, 2 pi) in double, losing about |x| 1e-16 rad.
#pragma once

namespace collide {

struct SinCos {
    double sin, cos;
};

// sin x and cos x. NaN for a NaN or infinite x.
SinCos sin_cos(double x);

}  // namespace collide
