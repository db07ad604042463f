#pragma once

namespace punchsweep::sweep {

/// Makes FFTW choose its plans without timing them, for the rest of the process, so that a
/// reference (BEM) point gives the same bits in every process.
///
/// The reference solver plans its transforms with FFTW_MEASURE, which picks among several
/// algorithms by timing them. They round differently, so two processes (two ranks, or a run
/// and its resumption) could give one point values that differ in the last bits, and near a
/// tie even another regime. With a zero planning time limit FFTW keeps the plan of its
/// estimate pass, a pure function of the transform size and the machine. The price is a
/// slightly slower transform (about 10-20% of a BEM point at N = 64-128, measured).
/// Call it before the first reference solve: plans already made stay as they are.
void use_reproducible_fft_plans();

}  // namespace punchsweep::sweep
