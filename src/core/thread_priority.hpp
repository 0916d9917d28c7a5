// Background work that must not slow the window down: the designer's tree builder and
// preview renderer run at a lower scheduling priority, and so do the threads they start
// (llvmpipe's rasteriser threads inherit their creator's niceness).
#pragma once

namespace eco {

// Lowers the calling thread's priority (nice +10 on Linux); does nothing where it cannot.
void lowerThisThreadsPriority();

}  // namespace eco
