// Compiled only by the ctest tests architecture.ForbiddenInclude.*: a file of one
// module that includes FLAPSIM_FORBIDDEN_HEADER, a header of a module it may not use
// (docs/architecture.md). The test passes when the compiler cannot find the header.
#include FLAPSIM_FORBIDDEN_HEADER
