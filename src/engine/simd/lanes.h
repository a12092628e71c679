#pragma once
// The lane width of the engine: the samples of a packet, the pixels of a run, the lanes of
// every vector loop. 16 floats are one AVX-512 register and one 64-byte cache line, and Embree
// traces 16-ray packets (rtcIntersect16). Every lane loop and lane array of the engine is sized
// by this constant; the intrinsics that assume it live in this folder and check it.
namespace gloss {

constexpr int kLanes = 16;

}  // namespace gloss
