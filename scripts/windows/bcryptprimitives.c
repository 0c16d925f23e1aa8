/* A stand-in for Windows' bcryptprimitives.dll, for running the workbook under Wine 8 (Debian
 * bookworm's) only: Rust's standard library (1.78 on) takes its random numbers, the seeds of
 * HashMap's hashing, from that DLL's ProcessPrng, which Windows 10 and 11 have and Wine 8 has not
 * (no .exe starts: "Library bcryptprimitives.dll ... not found", seen with WINEDEBUG=err+all). This
 * one forwards to advapi32's SystemFunction036 (RtlGenRandom), which Wine has. A real Windows never
 * sees it: scripts/windows.sh compiles it with mingw-w64 and puts it beside the .exe files it runs
 * under Wine.
 *
 *   x86_64-w64-mingw32-gcc -shared -O2 -o bcryptprimitives.dll bcryptprimitives.c -ladvapi32
 *
 * On x86_64 the exported name is the function's own: no .def file is needed. */
#include <windows.h>

/* advapi32's RtlGenRandom, exported under this name; fills `buffer` with `length` random bytes. */
BOOLEAN NTAPI SystemFunction036(PVOID buffer, ULONG length);

/* Fills `data` with `length` random bytes. Windows' own is documented to return TRUE always, and
 * Rust's standard library does not look; this one says FALSE where RtlGenRandom fails. */
__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    while (length > 0) {
        /* SystemFunction036 takes a ULONG (32 bits) length: large requests go in pieces. */
        ULONG piece = length > 0x40000000 ? 0x40000000 : (ULONG)length;
        if (!SystemFunction036(data, piece)) {
            return FALSE;
        }
        data += piece;
        length -= piece;
    }
    return TRUE;
}
