package carom.core.scene;

/**
 * The scenes benchmarks, experiments and long physics tests share, defined once so every figure
 * names the same workload.
 */
public final class StandardScenes {
    /** Collisions per disc the thesis's runs had: 55,000 collisions for 200,000 particles. */
    public static final double THESIS_COLLISIONS_PER_DISC = 0.275;
    /**
     * Simulated time that gives the thesis workload about {@link #THESIS_COLLISIONS_PER_DISC}
     * collisions per disc, calibrated on the serial engine (N = 1e5, seed 42: 0.273 per disc).
     */
    public static final double THESIS_UNTIL = 0.85;

    private StandardScenes() {
    }

    /**
     * The thesis's workload (Schrock 2016, ch. 4): discs evenly spaced on a lattice, pushed by a small
     * random jitter, with uniformly random velocity components, in a walled box. Here: unit lattice
     * pitch (a square box of side sqrt(N)), radius 0.2 (packing fraction 0.126), components uniform in
     * [-1, 1], jitter 0.1, one seed per trial.
     */
    public static Scene thesis(int discs, long seed) {
        double side = Math.sqrt(discs);
        return SceneBuilder.create("thesis-" + discs + "-seed" + seed)
                .box(side, side, BoundaryKind.WALLS)
                .species(Species.mobile("disc", 0.2, 1.0))
                .generate(new GenerateBlock(0, discs, 0.1, new VelocityDistribution.Uniform(1.0), seed))
                .until(THESIS_UNTIL)
                .build();
    }

    /**
     * An equilibrium-like hard-disc gas: N unit-mass discs of radius 0.5 on the lattice (jitter 0.5)
     * with Maxwell velocities at temperature 1, in a square box sized for packing fraction
     * {@code phi}, periodic or walled.
     */
    public static Scene gas(int discs, double phi, boolean periodic, double until, long seed) {
        double radius = 0.5;
        double side = Math.sqrt(discs * Math.PI * radius * radius / phi);
        return SceneBuilder.create(String.format("gas-%d-phi%s-%s", discs, phi, periodic ? "periodic" : "walls"))
                .box(side, side, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS)
                .species(Species.mobile("disc", radius, 1.0))
                .generate(new GenerateBlock(0, discs, 0.5, new VelocityDistribution.Maxwell(1.0), seed))
                .until(until)
                .build();
    }
}
