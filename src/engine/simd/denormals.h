#pragma once
// Flush-to-zero and denormals-are-zero for the renderer's worker threads: denormal results at
// high shininess must not slow rendering down (spec: "Denormal results must not slow rendering
// down"). SSE's MXCSR, present on every x86-64 CPU.
#include <xmmintrin.h>

namespace gloss {

// Sets FTZ and DAZ in MXCSR for its lifetime, then restores the caller's mode.
class DenormalsOff {
 public:
  DenormalsOff() : m_saved(_mm_getcsr()) { _mm_setcsr(m_saved | 0x8040u); }
  ~DenormalsOff() { _mm_setcsr(m_saved); }
  DenormalsOff(const DenormalsOff&) = delete;
  DenormalsOff& operator=(const DenormalsOff&) = delete;

 private:
  unsigned m_saved;
};

}  // namespace gloss
