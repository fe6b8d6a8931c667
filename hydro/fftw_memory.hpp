// FFTW's aligned buffers owned by std::unique_ptr: fftw_alloc_* paired with fftw_free.
#pragma once

#include <fftw3.h>

namespace ffrf::hydro {

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

}  // namespace ffrf::hydro
