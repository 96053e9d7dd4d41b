/* A plain FMI 2.0 Co-Simulation host for the platform checks (tests/platforms/run.sh).
 * The same source is compiled natively (cc), for Windows (x86_64-w64-mingw32-gcc, run
 * under wine) and for aarch64 Linux (aarch64-linux-gnu-gcc, run under qemu-aarch64);
 * run.sh compares what the builds print (tests/platforms/compare.py).
 *
 *   host <PinJoint binary> <PinJoint GUID> <PinJointRig binary> <PinJointRig GUID>
 *
 * Prints one line per result, "<tag> <values>", every number with %.17g (17 significant
 * digits read back to the same double):
 *   PinJoint <fidelity> <case> <load> <omega> <10 outputs, value references 10..19>
 *     the friction law over a grid of loads (0 N to 150 kN) and speeds (-50 to
 *     50 rad/s, zero and inside the zero-speed band included), one step of 1 ms each,
 *     at fidelity 0 (full) and 1 (table), zero_velocity.model = band (the stateless law the
 *     library's torque is compared with); then case "mu011_band0": boundary friction
 *     0.11 and the zero-speed band off; then case "presliding": the same grid at fidelity 0
 *     with the default zero-velocity model (presliding: the torque carries the state from
 *     point to point, driven by the angle input's increments);
 *   PinJointRig <fidelity> <step> <time> <11 Real outputs> <stuck>
 *     the rig (default 1 Hz, 40 deg sine) under 20 kN, 1.5 s in steps of 0.05 s;
 *   check <name> ok
 *     misuse and panic containment: a NaN input is refused with fmi2Error, and a panic
 *     forced inside fmi2DoStep (pinjoint_test_force_panic, the binary's test hook)
 *     returns fmi2Fatal and logs it, instead of aborting the process: the binary
 *     unwinds (the cross-built ones link their own unwinder).
 * Exit status 0 when every call returned what it must, 1 otherwise, 2 on a load failure.
 */
#include "../c/fmi2_host.h"

static int failures = 0;
#define EXPECT(call, want) do { int s_ = (call); if (s_ != (want)) { \
    fprintf(stderr, "line %d: %s returned %d, expected %d (last message: %s)\n", __LINE__, #call, s_, want, last_message); \
    failures++; } } while (0)

static const Callbacks callbacks = {logger, NULL, NULL, NULL, NULL};

/* Instantiate, set the Real parameters vr[i] = x[i], the Integer fidelity and, when
 * model_vr is not 0, the Integer (Enumeration) model, initialize. */
static C start(const Api *a, const char *guid, const VR *vr, const double *x, size_t n, VR fid_vr, int fidelity, VR model_vr, int model) {
    C c = a->Instantiate("platform", 1, guid, "", &callbacks, 0, 0);
    if (!c) { fprintf(stderr, "fmi2Instantiate returned NULL: %s\n", last_message); exit(1); }
    EXPECT(a->SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), FMI_OK);
    if (n > 0) EXPECT(a->SetReal(c, vr, n, x), FMI_OK);
    EXPECT(a->SetInteger(c, &fid_vr, 1, &fidelity), FMI_OK);
    if (model_vr != 0) EXPECT(a->SetInteger(c, &model_vr, 1, &model), FMI_OK);
    EXPECT(a->EnterInitializationMode(c), FMI_OK);
    EXPECT(a->ExitInitializationMode(c), FMI_OK);
    return c;
}

static void print_values(const double *y, size_t n) {
    for (size_t i = 0; i < n; i++) printf(" %.17g", y[i]);
}

/* PinJoint: value references of its variables (modelDescription/PinJoint.xml). */
static const VR PJ_IN[3] = {1, 2, 3};          /* angle, angular_velocity, load */
static const VR PJ_OUT[10] = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
static const VR PJ_FIDELITY = 300, PJ_MU_C = 120, PJ_BAND = 200, PJ_MODEL = 201;
/* zero_velocity.model: 0 band, 1 presliding (the default); -1: not set. */
enum { BAND = 0, DEFAULT_MODEL = -1 };

static void pin_joint_grid(const Api *a, const char *guid, const char *tag, int fidelity, int model, const VR *vr, const double *x, size_t n) {
    /* Inside the film-clearance bound (docs/conventions.md): 1 kN fails above ~25 rad/s, 2 kN at 83.8. */
    static const double loads[] = {0.0, 2e3, 5e3, 20e3, 60e3, 150e3};
    static const double speeds[] = {-50.0, -6.0, -0.21, -0.02, -0.004, 0.0, 1e-4, 0.004, 0.0101, 0.02, 0.21, 1.0, 6.0, 50.0};
    C c = start(a, guid, vr, x, n, PJ_FIDELITY, fidelity, model < 0 ? 0 : PJ_MODEL, model);
    double t = 0.0, h = 1e-3, y[10];
    for (size_t i = 0; i < sizeof loads / sizeof *loads; i++)
        for (size_t j = 0; j < sizeof speeds / sizeof *speeds; j++) {
            double u[3] = {t, speeds[j], loads[i]};
            EXPECT(a->SetReal(c, PJ_IN, 3, u), FMI_OK);
            EXPECT(a->DoStep(c, t, h, 1), FMI_OK);
            t += h;
            EXPECT(a->GetReal(c, PJ_OUT, 10, y), FMI_OK);
            printf("PinJoint %d %s %.17g %.17g", fidelity, tag, loads[i], speeds[j]);
            print_values(y, 10);
            printf("\n");
        }
    EXPECT(a->Terminate(c), FMI_OK);
    a->FreeInstance(c);
}

/* PinJointRig (modelDescription/PinJointRig.xml). */
static const VR RIG_LOAD = 1, RIG_FIDELITY = 400, RIG_STUCK = 17;
static const VR RIG_OUT[11] = {10, 11, 12, 13, 14, 15, 16, 18, 19, 20, 21};

static void rig(const Api *a, const char *guid, int fidelity) {
    C c = start(a, guid, NULL, NULL, 0, RIG_FIDELITY, fidelity, 0, 0);
    double load = 20e3, t = 0.0, h = 0.05, y[11];
    int stuck = 0;
    EXPECT(a->SetReal(c, &RIG_LOAD, 1, &load), FMI_OK);
    for (int k = 1; k <= 30; k++) {
        EXPECT(a->DoStep(c, t, h, 1), FMI_OK);
        t = k * h;
        EXPECT(a->GetReal(c, RIG_OUT, 11, y), FMI_OK);
        EXPECT(a->GetBoolean(c, &RIG_STUCK, 1, &stuck), FMI_OK);
        printf("PinJointRig %d %d %.17g", fidelity, k, t);
        print_values(y, 11);
        printf(" %d\n", stuck);
    }
    EXPECT(a->Terminate(c), FMI_OK);
    a->FreeInstance(c);
}

static void checks(const Api *a, const char *guid) {
    C c = start(a, guid, NULL, NULL, 0, PJ_FIDELITY, 0, 0, 0);
    double bad = NAN;
    EXPECT(a->SetReal(c, &PJ_IN[2], 1, &bad), FMI_ERROR);
    if (last_status != FMI_ERROR) { fprintf(stderr, "NaN load: no error logged\n"); failures++; }
    else printf("check nan_input_refused ok\n");

    double u[3] = {0.0, 1.0, 20e3};
    EXPECT(a->SetReal(c, PJ_IN, 3, u), FMI_OK);
    EXPECT(a->force_panic("fmi2DoStep"), 0);
    last_status = -1;
    EXPECT(a->DoStep(c, 0.0, 1e-3, 1), FMI_FATAL); /* an abort here ends the process: no unwinding */
    if (last_status != FMI_FATAL || !strstr(last_message, "forced panic in fmi2DoStep")) {
        fprintf(stderr, "forced panic: status %d, message '%s'\n", last_status, last_message);
        failures++;
    } else {
        printf("check panic_contained ok\n");
    }
    EXPECT(a->DoStep(c, 0.0, 1e-3, 1), FMI_ERROR); /* fatal: only fmi2FreeInstance is accepted */
    a->FreeInstance(c);
}

int main(int argc, char **argv) {
    if (argc != 5) {
        fprintf(stderr, "usage: %s <PinJoint binary> <PinJoint GUID> <PinJointRig binary> <PinJointRig GUID>\n", argv[0]);
        return 2;
    }
    Api pj, rg;
    if (!fmi2_host_load(argv[1], &pj) || !fmi2_host_load(argv[3], &rg)) return 2;
    if (!pj.force_panic) { fprintf(stderr, "%s: missing pinjoint_test_force_panic\n", argv[1]); return 2; }
    for (int fidelity = 0; fidelity <= 1; fidelity++) pin_joint_grid(&pj, argv[2], "default", fidelity, BAND, NULL, NULL, 0);
    const VR vr[2] = {PJ_MU_C, PJ_BAND};
    const double x[2] = {0.11, 0.0};
    pin_joint_grid(&pj, argv[2], "mu011_band0", 0, BAND, vr, x, 2);
    pin_joint_grid(&pj, argv[2], "presliding", 0, DEFAULT_MODEL, NULL, NULL, 0);
    for (int fidelity = 0; fidelity <= 1; fidelity++) rig(&rg, argv[4], fidelity);
    checks(&pj, argv[2]);
    fflush(stdout);
    if (failures) { fprintf(stderr, "%d failed calls\n", failures); return 1; }
    return 0;
}
