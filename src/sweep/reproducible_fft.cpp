#include "sweep/reproducible_fft.hpp"

#include <fftw3.h>

#include "reference/fft_influence.hpp"

namespace punchsweep::sweep {

void use_reproducible_fft_plans() {
  // FFTW never times out its estimate pass, and a measuring pass with no time left gives
  // up at once, so the estimate's plan is the one kept.
  reference::prepare_fftw();
  fftw_set_timelimit(0.0);
}

}  // namespace punchsweep::sweep
