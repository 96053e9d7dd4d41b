/* A plain C FMI 2.0 host for the memory check (tests/valgrind.sh): dlopens the
 * FMU's shared library and runs N instantiate/initialize/step/free cycles with
 * FMU state get/set/serialize/deserialize, rejected calls (so that the error
 * paths allocate and log), and both terminate-then-free and free-without-terminate.
 *
 *   fmu_cycles <binary.so> <GUID> <cycles>
 *
 * Exits 0 when every call returned what it must; valgrind then judges the memory.
 */
#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

static long messages, errors;

static void logger(void *env, const char *name, int status, const char *category, const char *fmt, ...) {
    char buf[4096];
    va_list ap;
    (void)env; (void)name; (void)category;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    messages++;
    if (status >= 3) errors++;
    if (buf[0] == 0) { fprintf(stderr, "empty log message\n"); exit(2); }
}

typedef C (*fmi2Instantiate_t)(const char *, int, const char *, const char *, const Callbacks *, int, int);
typedef void (*fmi2FreeInstance_t)(C);
typedef int (*fmi2SetupExperiment_t)(C, int, double, double, int, double);
typedef int (*fmi2EnterInitializationMode_t)(C);
typedef int (*fmi2ExitInitializationMode_t)(C);
typedef int (*fmi2Terminate_t)(C);
typedef int (*fmi2Reset_t)(C);
typedef int (*fmi2SetReal_t)(C, const VR *, size_t, const double *);
typedef int (*fmi2GetReal_t)(C, const VR *, size_t, double *);
typedef int (*fmi2DoStep_t)(C, double, double, int);
typedef int (*fmi2GetFMUstate_t)(C, void **);
typedef int (*fmi2SetFMUstate_t)(C, void *);
typedef int (*fmi2FreeFMUstate_t)(C, void **);
typedef int (*fmi2SerializedFMUstateSize_t)(C, void *, size_t *);
typedef int (*fmi2SerializeFMUstate_t)(C, void *, char *, size_t);
typedef int (*fmi2DeSerializeFMUstate_t)(C, const char *, size_t, void **);
typedef int (*fmi2SetDebugLogging_t)(C, int, size_t, const char *const *);

#define LOAD(T, name) T name = (T)dlsym(lib, #name); if (!name) { fprintf(stderr, "missing %s\n", #name); return 2; }
#define EXPECT(call, want) do { int s_ = (call); if (s_ != (want)) { fprintf(stderr, "cycle %d: %s returned %d, expected %d\n", k, #call, s_, want); return 1; } } while (0)

int main(int argc, char **argv) {
    if (argc != 4) { fprintf(stderr, "usage: %s <binary.so> <GUID> <cycles>\n", argv[0]); return 2; }
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!lib) { fprintf(stderr, "dlopen: %s\n", dlerror()); return 2; }
    const char *guid = argv[2];
    int cycles = atoi(argv[3]);

    LOAD(fmi2Instantiate_t, fmi2Instantiate)
    LOAD(fmi2FreeInstance_t, fmi2FreeInstance)
    LOAD(fmi2SetupExperiment_t, fmi2SetupExperiment)
    LOAD(fmi2EnterInitializationMode_t, fmi2EnterInitializationMode)
    LOAD(fmi2ExitInitializationMode_t, fmi2ExitInitializationMode)
    LOAD(fmi2Terminate_t, fmi2Terminate)
    LOAD(fmi2Reset_t, fmi2Reset)
    LOAD(fmi2SetReal_t, fmi2SetReal)
    LOAD(fmi2GetReal_t, fmi2GetReal)
    LOAD(fmi2DoStep_t, fmi2DoStep)
    LOAD(fmi2GetFMUstate_t, fmi2GetFMUstate)
    LOAD(fmi2SetFMUstate_t, fmi2SetFMUstate)
    LOAD(fmi2FreeFMUstate_t, fmi2FreeFMUstate)
    LOAD(fmi2SerializedFMUstateSize_t, fmi2SerializedFMUstateSize)
    LOAD(fmi2SerializeFMUstate_t, fmi2SerializeFMUstate)
    LOAD(fmi2DeSerializeFMUstate_t, fmi2DeSerializeFMUstate)
    LOAD(fmi2SetDebugLogging_t, fmi2SetDebugLogging)

    Callbacks cb = {logger, NULL, NULL, NULL, NULL};
    const VR in[3] = {1, 2, 3};             /* angle, angular_velocity, load */
    const VR out[10] = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
    const VR mu_c = 120, bad = 9999;
    double y[10], first[10];
    int k;
    for (k = 0; k < cycles; k++) {
        C c = fmi2Instantiate("valgrind", 1, guid, "file:///tmp", &cb, 0, k % 7 == 0);
        if (!c) { fprintf(stderr, "cycle %d: fmi2Instantiate returned NULL\n", k); return 1; }
        EXPECT(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), 0);
        double m = 0.1 + 0.0001 * (k % 100);
        EXPECT(fmi2SetReal(c, &mu_c, 1, &m), 0);
        EXPECT(fmi2EnterInitializationMode(c), 0);
        EXPECT(fmi2ExitInitializationMode(c), 0);
        void *state = NULL, *copy = NULL;
        double t = 0.0, h = 1e-3;
        for (int i = 0; i < 20; i++) {
            double u[3] = {0.01 * i, 2.0 * sin(0.3 * i + k), 5e3 + 1e3 * i};
            EXPECT(fmi2SetReal(c, in, 3, u), 0);
            EXPECT(fmi2DoStep(c, t, h, 0), 0);
            t += h;
            EXPECT(fmi2GetReal(c, out, 10, y), 0);
            for (int j = 0; j < 10; j++) if (!isfinite(y[j])) { fprintf(stderr, "cycle %d: output %d not finite\n", k, j); return 1; }
            if (i == 5) {
                EXPECT(fmi2GetFMUstate(c, &state), 0);
                memcpy(first, y, sizeof y);
            }
        }
        /* Rejected calls: they allocate and log their messages. */
        double nan = NAN;
        EXPECT(fmi2SetReal(c, &in[2], 1, &nan), 3);
        EXPECT(fmi2SetReal(c, &bad, 1, &m), 3);
        EXPECT(fmi2DoStep(c, t + 1.0, h, 0), 3);
        EXPECT(fmi2EnterInitializationMode(c), 3);
        const char *cats[] = {"logNoSuchCategory"};
        EXPECT(fmi2SetDebugLogging(c, 1, 1, cats), 3);
        /* State: serialize, damage, deserialize, restore, re-step. */
        size_t n = 0;
        EXPECT(fmi2SerializedFMUstateSize(c, state, &n), 0);
        char *blob = malloc(n);
        EXPECT(fmi2SerializeFMUstate(c, state, blob, n), 0);
        EXPECT(fmi2DeSerializeFMUstate(c, blob, n, &copy), 0);
        blob[n / 2] ^= 0x40;
        void *rejected = NULL;
        EXPECT(fmi2DeSerializeFMUstate(c, blob, n, &rejected), 3);
        EXPECT(fmi2DeSerializeFMUstate(c, blob, n - 7, &rejected), 3);
        free(blob);
        EXPECT(fmi2SetFMUstate(c, copy), 0);
        EXPECT(fmi2GetReal(c, out, 10, y), 0);
        if (memcmp(y, first, sizeof y) != 0) { fprintf(stderr, "cycle %d: restored outputs differ\n", k); return 1; }
        EXPECT(fmi2GetFMUstate(c, &state), 0); /* reuse of an existing state object */
        EXPECT(fmi2FreeFMUstate(c, &state), 0);
        EXPECT(fmi2FreeFMUstate(c, &copy), 0);
        if (k % 3 == 0) {
            EXPECT(fmi2Terminate(c), 0);
            EXPECT(fmi2Terminate(c), 3);
            if (k % 2 == 0) {
                EXPECT(fmi2Reset(c), 0);
            }
        }
        /* k % 3 != 0: free without terminate. */
        fmi2FreeInstance(c);
    }
    /* Instantiation failures free what they allocated. */
    if (fmi2Instantiate("bad", 1, "{not-a-guid}", "", &cb, 0, 0) != NULL) { fprintf(stderr, "wrong GUID accepted\n"); return 1; }
    if (fmi2Instantiate("bad", 7, guid, "", &cb, 0, 0) != NULL) { fprintf(stderr, "fmuType 7 accepted\n"); return 1; }
    /* PinJoint is also Model Exchange (issue 11): an ME instance through its life cycle, freed. */
    {
        C me = fmi2Instantiate("me", 0, guid, NULL, &cb, 0, 0);
        if (me == NULL) { fprintf(stderr, "Model Exchange refused\n"); return 1; }
        fmi2FreeInstance(me);
    }
    if (errors < 7L * cycles) { fprintf(stderr, "only %ld error messages in %d cycles\n", errors, cycles); return 1; }
    printf("%d cycles, %ld log messages (%ld errors)\n", cycles, messages, errors);
    dlclose(lib);
    return 0;
}
