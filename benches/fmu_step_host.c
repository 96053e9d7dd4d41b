/* A plain C FMI 2.0 host that runs the fmpy benchmark's loop (benches/fmu_step.py) without
 * Python, for the instruction profile of one PinJoint step (benches/callgrind.sh): set
 * angular_velocity and load, fmi2DoStep, get torque and friction_coefficient, for STEPS
 * steps of 1 ms along a 1 Hz +-40 deg stroke at 20 kN +- 10 %.
 *
 *   fmu_step_host <binary.so> <GUID> <fidelity code> <steps> <vr omega> <vr load> <vr torque> <vr mu> <vr fidelity>
 */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

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

static void logger(void *env, const char *name, int status, const char *category, const char *fmt, ...) {
    (void)env; (void)name; (void)status; (void)category; (void)fmt;
}

typedef C (*inst_t)(const char *, int, const char *, const char *, const Callbacks *, int, int);
typedef int (*c_t)(C);
typedef int (*setup_t)(C, int, double, double, int, double);
typedef int (*setr_t)(C, const VR *, size_t, const double *);
typedef int (*getr_t)(C, const VR *, size_t, double *);
typedef int (*seti_t)(C, const VR *, size_t, const int *);
typedef int (*step_t)(C, double, double, int);
typedef void (*free_t)(C);

#define LOAD(T, v, name) T v = (T)dlsym(lib, name); if (!v) { fprintf(stderr, "missing %s\n", name); return 2; }

int main(int argc, char **argv) {
    if (argc != 10) { fprintf(stderr, "usage: %s <binary.so> <GUID> <fidelity> <steps> <vr omega> <vr load> <vr torque> <vr mu> <vr fidelity>\n", argv[0]); return 2; }
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!lib) { fprintf(stderr, "dlopen: %s\n", dlerror()); return 2; }
    int fidelity = atoi(argv[3]);
    long steps = atol(argv[4]);
    VR in[2] = {(VR)atoi(argv[5]), (VR)atoi(argv[6])}, out[2] = {(VR)atoi(argv[7]), (VR)atoi(argv[8])}, fid = (VR)atoi(argv[9]);
    LOAD(inst_t, instantiate, "fmi2Instantiate")
    LOAD(setup_t, setup, "fmi2SetupExperiment")
    LOAD(c_t, enter, "fmi2EnterInitializationMode")
    LOAD(c_t, exit_, "fmi2ExitInitializationMode")
    LOAD(setr_t, setr, "fmi2SetReal")
    LOAD(getr_t, getr, "fmi2GetReal")
    LOAD(seti_t, seti, "fmi2SetInteger")
    LOAD(step_t, step, "fmi2DoStep")
    LOAD(c_t, terminate, "fmi2Terminate")
    LOAD(free_t, freei, "fmi2FreeInstance")
    Callbacks cb = {logger, calloc, free, NULL, NULL};
    C c = instantiate("host", 1, argv[2], "", &cb, 0, 0);
    if (!c) { fprintf(stderr, "instantiate failed\n"); return 1; }
    if (setup(c, 0, 0.0, 0.0, 0, 0.0) || seti(c, &fid, 1, &fidelity) || enter(c) || exit_(c)) { fprintf(stderr, "initialization failed\n"); return 1; }
    double h = 1e-3, t = 0.0, y[2], sum = 0.0;
    for (long k = 0; k < steps; k++) {
        double u[2] = {2 * M_PI * 40.0 * M_PI / 180.0 * cos(2 * M_PI * t), 20e3 * (1 + 0.1 * sin(2 * M_PI * 0.3 * t))};
        if (setr(c, in, 2, u) || step(c, t, h, 1) || getr(c, out, 2, y)) { fprintf(stderr, "step %ld failed\n", k); return 1; }
        sum += y[0];
        t += h;
    }
    terminate(c);
    freei(c);
    printf("%.17g\n", sum);
    return 0;
}
