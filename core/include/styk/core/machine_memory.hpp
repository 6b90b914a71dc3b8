// The memory of the machine the program runs on, for the checks that refuse a job which will not
// fit before it starts allocating (the direct solver's factor, the mesher's blocks).
#pragma once

namespace styk {

// Bytes of physical memory; 0 when the system does not say.
double physical_memory_bytes();

}  // namespace styk
