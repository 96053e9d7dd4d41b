/* Test-only stand-in for Windows' bcryptprimitives.dll, for running the win64 FMU
 * binary under Wine 8, which lacks that DLL. The Rust standard library for Windows 10+
 * imports ProcessPrng from it (random keys of HashMap); Windows 10 and later ship it, so
 * the FMU never needs this file on Windows. ProcessPrng is forwarded to RtlGenRandom
 * (advapi32's SystemFunction036), which Wine has. Built by tests/platforms/run.sh with
 *   x86_64-w64-mingw32-gcc -shared -o bcryptprimitives.dll bcryptprimitives.c -ladvapi32
 * and put beside the host executable; never packaged. */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T len) {
    while (len > 0) {
        ULONG chunk = len > 0x10000000 ? 0x10000000 : (ULONG)len;
        if (!SystemFunction036(data, chunk)) return FALSE;
        data += chunk;
        len -= chunk;
    }
    return TRUE;
}
