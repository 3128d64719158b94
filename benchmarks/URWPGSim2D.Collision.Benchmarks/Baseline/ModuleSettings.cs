using System.Runtime.CompilerServices;

// As in the library: stack buffers are written before they are read, so the frozen kernels (and
// the rest of the benchmarks) skip zeroing them, and a baseline costs what it cost in the library.
[module: SkipLocalsInit]
