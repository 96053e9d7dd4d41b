/* A plain C FMI 2.0 host for the memory check (tests/valgrind.sh): dlopens the
 * FMU's shared library and runs N instantiate/initialize/step/free cycles with
 * FMU state get/set/serialize/deserialize, rejected calls (so that the error
 * paths allocate and log), and both terminate-then-free and free-without-terminate.
 *
 *   fmu_cycles <binary.so> <GUID> <cycles>
 *
 * Exits 0 when every call returned what it must; valgrind then judges the memory.
 */
#include "../c/fmi2_host.h"

#define EXPECT(call, want) do { int s_ = (call); if (s_ != (want)) { fprintf(stderr, "cycle %d: %s returned %d, expected %d\n", k, #call, s_, want); return 1; } } while (0)

int main(int argc, char **argv) {
    if (argc != 4) { fprintf(stderr, "usage: %s <binary.so> <GUID> <cycles>\n", argv[0]); return 2; }
    Api a;
    if (!fmi2_host_load(argv[1], &a)) return 2;
    const char *guid = argv[2];
    int cycles = atoi(argv[3]);

    Callbacks cb = {logger, NULL, NULL, NULL, NULL};
    const VR in[3] = {1, 2, 3};             /* angle, angular_velocity, load */
    const VR out[10] = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
    const VR mu_c = 120, bad = 9999;
    double y[10], first[10];
    int k;
    for (k = 0; k < cycles; k++) {
        C c = a.Instantiate("valgrind", 1, guid, "file:///tmp", &cb, 0, k % 7 == 0);
        if (!c) { fprintf(stderr, "cycle %d: fmi2Instantiate returned NULL\n", k); return 1; }
        EXPECT(a.SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), 0);
        double m = 0.1 + 0.0001 * (k % 100);
        EXPECT(a.SetReal(c, &mu_c, 1, &m), 0);
        EXPECT(a.EnterInitializationMode(c), 0);
        EXPECT(a.ExitInitializationMode(c), 0);
        void *state = NULL, *copy = NULL;
        double t = 0.0, h = 1e-3;
        for (int i = 0; i < 20; i++) {
            double u[3] = {0.01 * i, 2.0 * sin(0.3 * i + k), 5e3 + 1e3 * i};
            EXPECT(a.SetReal(c, in, 3, u), 0);
            EXPECT(a.DoStep(c, t, h, 0), 0);
            t += h;
            EXPECT(a.GetReal(c, out, 10, y), 0);
            for (int j = 0; j < 10; j++) if (!isfinite(y[j])) { fprintf(stderr, "cycle %d: output %d not finite\n", k, j); return 1; }
            if (i == 5) {
                EXPECT(a.GetFMUstate(c, &state), 0);
                memcpy(first, y, sizeof y);
            }
        }
        /* Rejected calls: they allocate and log their messages. */
        double nan = NAN;
        EXPECT(a.SetReal(c, &in[2], 1, &nan), 3);
        EXPECT(a.SetReal(c, &bad, 1, &m), 3);
        EXPECT(a.DoStep(c, t + 1.0, h, 0), 3);
        EXPECT(a.EnterInitializationMode(c), 3);
        const char *cats[] = {"logNoSuchCategory"};
        EXPECT(a.SetDebugLogging(c, 1, 1, cats), 3);
        /* State: serialize, damage, deserialize, restore, re-step. */
        size_t n = 0;
        EXPECT(a.SerializedFMUstateSize(c, state, &n), 0);
        char *blob = malloc(n);
        EXPECT(a.SerializeFMUstate(c, state, blob, n), 0);
        EXPECT(a.DeSerializeFMUstate(c, blob, n, &copy), 0);
        blob[n / 2] ^= 0x40;
        void *rejected = NULL;
        EXPECT(a.DeSerializeFMUstate(c, blob, n, &rejected), 3);
        EXPECT(a.DeSerializeFMUstate(c, blob, n - 7, &rejected), 3);
        free(blob);
        EXPECT(a.SetFMUstate(c, copy), 0);
        EXPECT(a.GetReal(c, out, 10, y), 0);
        if (memcmp(y, first, sizeof y) != 0) { fprintf(stderr, "cycle %d: restored outputs differ\n", k); return 1; }
        EXPECT(a.GetFMUstate(c, &state), 0); /* reuse of an existing state object */
        EXPECT(a.FreeFMUstate(c, &state), 0);
        EXPECT(a.FreeFMUstate(c, &copy), 0);
        if (k % 3 == 0) {
            EXPECT(a.Terminate(c), 0);
            EXPECT(a.Terminate(c), 3);
            if (k % 2 == 0) {
                EXPECT(a.Reset(c), 0);
            }
        }
        /* k % 3 != 0: free without terminate. */
        a.FreeInstance(c);
    }
    /* Instantiation failures free what they allocated. */
    if (a.Instantiate("bad", 1, "{not-a-guid}", "", &cb, 0, 0) != NULL) { fprintf(stderr, "wrong GUID accepted\n"); return 1; }
    if (a.Instantiate("bad", 7, guid, "", &cb, 0, 0) != NULL) { fprintf(stderr, "fmuType 7 accepted\n"); return 1; }
    /* PinJoint is also Model Exchange (issue 11): an ME instance through its life cycle, freed. */
    {
        C me = a.Instantiate("me", 0, guid, NULL, &cb, 0, 0);
        if (me == NULL) { fprintf(stderr, "Model Exchange refused\n"); return 1; }
        a.FreeInstance(me);
    }
    if (log_errors < 7L * cycles) { fprintf(stderr, "only %ld error messages in %d cycles\n", log_errors, cycles); return 1; }
    printf("%d cycles, %ld log messages (%ld errors)\n", cycles, log_messages, log_errors);
    lib_close(a.lib);
    return 0;
}
