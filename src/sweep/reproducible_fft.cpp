#include "sweep/reproducible_fft.hpp"

#include <fftw3.h>

namespace punchsweep::sweep {

void use_reproducible_fft_plans() {
  // FFTW never times out its estimate pass, and a measuring pass with no time left gives
  // up at once, so the estimate's plan is the one kept.
  fftw_set_timelimit(0.0);
}

}  // namespace punchsweep::sweep
