/* What the plain C FMI 2.0 hosts share (tests/platforms/host.c, tests/valgrind/fmu_cycles.c,
 * benches/fmu_step_host.c): the FMI 2.0 C types they use, a logger that keeps the last
 * message and counts them, and a loader of the fmi2 functions from a shared library
 * (dlopen, or LoadLibraryA on Windows). Header only: each host is one translation unit
 * that includes it, so every host still compiles with one command.
 *
 * The logger ends the process with status 2 on an empty message (the FMU must always say
 * what happened).
 */
#ifndef PINJOINT_FMI2_HOST_H
#define PINJOINT_FMI2_HOST_H

#if defined(_WIN32)
#define __USE_MINGW_ANSI_STDIO 1 /* mingw's C99 printf: %.17g exact whatever the C runtime */
#endif
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(_WIN32)
#include <windows.h>
typedef HMODULE Lib;
static inline Lib lib_open(const char *path) { return LoadLibraryA(path); }
static inline void *lib_sym(Lib l, const char *name) { return (void *)GetProcAddress(l, name); }
static inline void lib_close(Lib l) { FreeLibrary(l); }
static inline const char *lib_error(void) { static char buf[64]; snprintf(buf, sizeof buf, "Windows error %lu", (unsigned long)GetLastError()); return buf; }
#else
#include <dlfcn.h>
typedef void *Lib;
static inline Lib lib_open(const char *path) { return dlopen(path, RTLD_NOW | RTLD_LOCAL); }
static inline void *lib_sym(Lib l, const char *name) { return dlsym(l, name); }
static inline void lib_close(Lib l) { dlclose(l); }
static inline const char *lib_error(void) { return dlerror(); }
#endif

typedef void *C;
typedef unsigned int VR;
typedef void (*Logger)(void *, const char *, int, const char *, const char *, ...);
typedef struct {
    Logger logger;
    void *(*allocateMemory)(size_t, size_t);
    void (*freeMemory)(void *);
    void (*stepFinished)(void *, int);
    void *componentEnvironment;
} Callbacks;

enum { FMI_OK = 0, FMI_ERROR = 3, FMI_FATAL = 4 };

/* What the logger saw: the last status and message, how many messages, how many of them
 * with status fmi2Error or worse. */
static int last_status = -1;
static char last_message[4096];
static long log_messages, log_errors;

static inline void logger(void *env, const char *name, int status, const char *category, const char *fmt, ...) {
    va_list ap;
    (void)env; (void)name; (void)category;
    va_start(ap, fmt);
    vsnprintf(last_message, sizeof last_message, fmt, ap);
    va_end(ap);
    last_status = status;
    log_messages++;
    if (status >= FMI_ERROR) log_errors++;
    if (last_message[0] == 0) { fprintf(stderr, "empty log message\n"); exit(2); }
}

/* The FMI 2.0 functions the hosts call, and the library they come from. */
typedef struct {
    Lib lib;
    C (*Instantiate)(const char *, int, const char *, const char *, const Callbacks *, int, int);
    void (*FreeInstance)(C);
    int (*SetupExperiment)(C, int, double, double, int, double);
    int (*EnterInitializationMode)(C);
    int (*ExitInitializationMode)(C);
    int (*Terminate)(C);
    int (*Reset)(C);
    int (*SetDebugLogging)(C, int, size_t, const char *const *);
    int (*SetReal)(C, const VR *, size_t, const double *);
    int (*GetReal)(C, const VR *, size_t, double *);
    int (*SetInteger)(C, const VR *, size_t, const int *);
    int (*GetBoolean)(C, const VR *, size_t, int *);
    int (*DoStep)(C, double, double, int);
    int (*GetFMUstate)(C, void **);
    int (*SetFMUstate)(C, void *);
    int (*FreeFMUstate)(C, void **);
    int (*SerializedFMUstateSize)(C, void *, size_t *);
    int (*SerializeFMUstate)(C, void *, char *, size_t);
    int (*DeSerializeFMUstate)(C, const char *, size_t, void **);
    /* The binary's test hook (pinjoint_test_force_panic); NULL where it is not exported. */
    int (*force_panic)(const char *);
} Api;

/* Load the library at `path` and every fmi2 function of `Api`: 1 on success, 0 (after
 * saying what is missing on stderr) otherwise. */
static inline int fmi2_host_load(const char *path, Api *a) {
    Lib l = lib_open(path);
    if (!l) { fprintf(stderr, "cannot load %s: %s\n", path, lib_error()); return 0; }
    void *p;
    memset(a, 0, sizeof *a);
    a->lib = l;
    /* Object to function pointer through memcpy (ISO C has no cast between them). */
#define SYM(field, name) if (!(p = lib_sym(l, name))) { fprintf(stderr, "%s: missing %s\n", path, name); return 0; } \
    memcpy(&a->field, &p, sizeof p);
    SYM(Instantiate, "fmi2Instantiate")
    SYM(FreeInstance, "fmi2FreeInstance")
    SYM(SetupExperiment, "fmi2SetupExperiment")
    SYM(EnterInitializationMode, "fmi2EnterInitializationMode")
    SYM(ExitInitializationMode, "fmi2ExitInitializationMode")
    SYM(Terminate, "fmi2Terminate")
    SYM(Reset, "fmi2Reset")
    SYM(SetDebugLogging, "fmi2SetDebugLogging")
    SYM(SetReal, "fmi2SetReal")
    SYM(GetReal, "fmi2GetReal")
    SYM(SetInteger, "fmi2SetInteger")
    SYM(GetBoolean, "fmi2GetBoolean")
    SYM(DoStep, "fmi2DoStep")
    SYM(GetFMUstate, "fmi2GetFMUstate")
    SYM(SetFMUstate, "fmi2SetFMUstate")
    SYM(FreeFMUstate, "fmi2FreeFMUstate")
    SYM(SerializedFMUstateSize, "fmi2SerializedFMUstateSize")
    SYM(SerializeFMUstate, "fmi2SerializeFMUstate")
    SYM(DeSerializeFMUstate, "fmi2DeSerializeFMUstate")
#undef SYM
    if ((p = lib_sym(l, "pinjoint_test_force_panic"))) memcpy(&a->force_panic, &p, sizeof p);
    return 1;
}

#endif
