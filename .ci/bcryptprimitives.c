/* Test scaffolding, never shipped: Debian's Wine 8 has no
 * bcryptprimitives.dll, whose ProcessPrng the Rust standard library imports
 * on Windows. This one hands the call to RtlGenRandom (SystemFunction036 of
 * advapi32), which Wine has. */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    return SystemFunction036(data, (ULONG)length);
}
