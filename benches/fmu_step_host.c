/* A plain C FMI 2.0 host that runs the fmpy benchmark's loop (benches/fmu_step.py) without
 * Python, for the instruction profile of one PinJoint step (benches/callgrind.sh): set
 * angular_velocity and load, fmi2DoStep, get torque and friction_coefficient, for STEPS
 * steps of 1 ms along a 1 Hz +-40 deg stroke at 20 kN +- 10 %.
 *
 *   fmu_step_host <binary.so> <GUID> <fidelity code> <steps> <vr omega> <vr load> <vr torque> <vr mu> <vr fidelity>
 */
#include "../tests/c/fmi2_host.h"

int main(int argc, char **argv) {
    if (argc != 10) { fprintf(stderr, "usage: %s <binary.so> <GUID> <fidelity> <steps> <vr omega> <vr load> <vr torque> <vr mu> <vr fidelity>\n", argv[0]); return 2; }
    Api a;
    if (!fmi2_host_load(argv[1], &a)) return 2;
    int fidelity = atoi(argv[3]);
    long steps = atol(argv[4]);
    VR in[2] = {(VR)atoi(argv[5]), (VR)atoi(argv[6])}, out[2] = {(VR)atoi(argv[7]), (VR)atoi(argv[8])}, fid = (VR)atoi(argv[9]);
    Callbacks cb = {logger, calloc, free, NULL, NULL};
    C c = a.Instantiate("host", 1, argv[2], "", &cb, 0, 0);
    if (!c) { fprintf(stderr, "instantiate failed\n"); return 1; }
    if (a.SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0) || a.SetInteger(c, &fid, 1, &fidelity) || a.EnterInitializationMode(c) || a.ExitInitializationMode(c)) { fprintf(stderr, "initialization failed\n"); return 1; }
    double h = 1e-3, t = 0.0, y[2], sum = 0.0;
    for (long k = 0; k < steps; k++) {
        double u[2] = {2 * M_PI * 40.0 * M_PI / 180.0 * cos(2 * M_PI * t), 20e3 * (1 + 0.1 * sin(2 * M_PI * 0.3 * t))};
        if (a.SetReal(c, in, 2, u) || a.DoStep(c, t, h, 1) || a.GetReal(c, out, 2, y)) { fprintf(stderr, "step %ld failed\n", k); return 1; }
        sum += y[0];
        t += h;
    }
    a.Terminate(c);
    a.FreeInstance(c);
    printf("%.17g\n", sum);
    return 0;
}
