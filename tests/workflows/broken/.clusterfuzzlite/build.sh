TARGETS=(fuzz_a fuzz_b)
