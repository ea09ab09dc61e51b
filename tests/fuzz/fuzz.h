/*
 * fuzz.h: what every fuzz target of tests/fuzz defines.
 *
 * A target is one function, LLVMFuzzerTestOneInput, that takes any bytes
 * and must never crash, hang, leak or misbehave under ASan and UBSan; it
 * aborts when it finds Facet wrong (two evaluators disagreeing). `make
 * fuzz` links each with libFuzzer (clang); replay.c links the same targets
 * into a plain program that runs the seed corpus and every crash input
 * found so far, in `make check`.
 */
#ifndef FACET_FUZZ_H
#define FACET_FUZZ_H

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#endif
