#pragma once
// Which instruction set the pixel code running in this process was compiled for: "native"
// (-march=native), "x86-64" (the compiler's baseline), or, in a build with GLOSS_ISA_VARIANTS,
// the level of the variant of libgloss_core.so that the dynamic loader chose for this CPU
// ("x86-64-v2", "x86-64-v3", "x86-64-v4"; docs/engine.md, "One build for every x86-64").
namespace gloss {

const char* pixel_code_isa();

}  // namespace gloss
