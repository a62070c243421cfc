package carom.lab.peer;

import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.physics.Boundary;
import carom.core.physics.Physics;
import carom.core.physics.Restitution;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.stepped.SteppedEngine;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.dynamics.Settings;
import org.dyn4j.dynamics.contact.Contact;
import org.dyn4j.dynamics.contact.SolvedContact;
import org.dyn4j.geometry.Circle;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Rectangle;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.ContactCollisionData;
import org.dyn4j.world.World;
import org.dyn4j.world.listener.ContactListenerAdapter;

/** One run of {@link Dyn4jPeer}: the scene built as a dyn4j world, stepped at dt, read back. */
final class Dyn4jRun {
    /** A dyn4j body that knows which disc (id >= 0) or wall (-1 - Boundary.LEFT ...) it is. */
    static final class Tagged extends Body {
        final int id;

        Tagged(int id) {
            this.id = id;
        }
    }

    private final Scene scene;
    private final Discs d;
    private final int n;
    private final double until;
    private final double dt;
    private final Restitution restitution;
    private final ProgressListener progress;
    private final World<Tagged> world = new World<>();
    private final Tagged[] bodies;
    /** Whether each disc was outside the box at the last step's end. */
    private final boolean[] outside;
    private final VirialAccumulator virial;

    /** Absolute time of the step being solved, for the restitution law. */
    private double stepEnd;
    private long pairCollisions;
    private long wallCollisions;
    private long escapes;
    private double deepestOverlap;

    Dyn4jRun(Scene scene, RunOptions options, double dt) {
        this.scene = scene;
        this.d = scene.newDiscs();
        this.n = d.n;
        this.until = options.until();
        this.dt = dt;
        this.restitution = Physics.of(scene).restitution;
        this.progress = options.progress();
        this.bodies = new Tagged[n];
        this.outside = new boolean[n];
        this.virial = VirialAccumulator.forRun(until);
        build();
    }

    private void build() {
        Settings settings = world.getSettings();
        settings.setAtRestDetectionEnabled(false);
        settings.setStepFrequency(1 / dt);
        world.setGravity(scene.effects().gravityX(), scene.effects().gravityY());
        double pairE = scene.effects().restitution();
        for (int i = 0; i < n; i++) {
            Tagged b = new Tagged(i);
            Circle circle = new Circle(d.radius[i]);
            boolean fixed = d.invMass[i] == 0;
            // Mass = density * area, so density = mass / (pi r^2) gives the species' mass.
            double density = fixed ? 1 : 1 / (d.invMass[i] * circle.getArea());
            addFixture(b, circle, density, pairE);
            b.translate(d.x[i], d.y[i]);
            b.setLinearVelocity(d.vx[i], d.vy[i]);
            b.setMass(fixed ? MassType.INFINITE : MassType.NORMAL);
            b.setLinearDamping(0);
            b.setAngularDamping(0);
            bodies[i] = b;
            world.addBody(b);
        }
        addWalls(scene.box().width(), scene.box().height(), scene.effects().wallRestitution());
        world.addContactListener(new Listener());
    }

    private static void addFixture(Tagged b, Convex shape, double density, double e) {
        BodyFixture f = b.addFixture(shape, density, 0, e);
        f.setRestitutionVelocity(0);
    }

    /** Four static slabs as thick as the box is large, their inner faces on the box's edges. */
    private void addWalls(double w, double h, double e) {
        double t = Math.max(w, h);
        wall(Boundary.LEFT, new Rectangle(t, h + 2 * t), -t / 2, h / 2, e);
        wall(Boundary.RIGHT, new Rectangle(t, h + 2 * t), w + t / 2, h / 2, e);
        wall(Boundary.BOTTOM, new Rectangle(w + 2 * t, t), w / 2, -t / 2, e);
        wall(Boundary.TOP, new Rectangle(w + 2 * t, t), w / 2, h + t / 2, e);
    }

    private void wall(int which, Rectangle shape, double cx, double cy, double e) {
        Tagged b = new Tagged(-1 - which);
        addFixture(b, shape, 1, e);
        b.translate(cx, cy);
        b.setMass(MassType.INFINITE);
        world.addBody(b);
    }

    RunResult run() {
        long started = System.nanoTime();
        double energyStart = Observables.kineticEnergy(d);
        double[] momentumStart = Observables.momentum(d);
        long steps = (long) Math.ceil(until / dt);
        double stepStart = 0;
        for (long k = 1; k <= steps; k++) {
            stepEnd = k == steps ? until : k * dt;
            world.step(1, stepEnd - stepStart);
            stepStart = stepEnd;
            countEscapes();
            progress.simulatedTime(stepEnd);
        }
        readBack();
        double seconds = (System.nanoTime() - started) * 1e-9;
        double energyEnd = Observables.kineticEnergy(d);
        Pressure pressure = VirialAccumulator.pressureOf(virial, scene, d, energyStart, energyEnd);
        return RunResult.of(Dyn4jPeer.SPEC.name(), Dyn4jPeer.SPEC.exact(), d, until)
                .collisions(pairCollisions, wallCollisions)
                .kineticEnergy(energyStart, energyEnd)
                .momentum(momentumStart, Observables.momentum(d))
                .pressure(pressure)
                .wallSeconds(seconds)
                .counters(SteppedEngine.counters(steps, escapes, deepestOverlap))
                .build();
    }

    private void countEscapes() {
        double w = scene.box().width();
        double h = scene.box().height();
        for (int i = 0; i < n; i++) {
            double x = bodies[i].getTransform().getTranslationX();
            double y = bodies[i].getTransform().getTranslationY();
            boolean out = x < 0 || x > w || y < 0 || y > h;
            if (out && !outside[i]) {
                escapes++;
            }
            outside[i] = out;
        }
    }

    private void readBack() {
        for (int i = 0; i < n; i++) {
            Tagged b = bodies[i];
            Vector2 v = b.getLinearVelocity();
            d.x[i] = b.getTransform().getTranslationX();
            d.y[i] = b.getTransform().getTranslationY();
            d.vx[i] = d.invMass[i] == 0 ? 0 : v.x;
            d.vy[i] = d.invMass[i] == 0 ? 0 : v.y;
            d.t[i] = until;
        }
    }

    /**
     * Before the solver: each contact gets the scene's restitution (dyn4j would mix the two fixtures'
     * values, which cannot tell a wall's from a disc's, nor apply the TC model), and its depth is the
     * overlap seen. After it: a contact that took a positive normal impulse is a collision, and a pair's
     * impulse J adds J |r| to the virial (r the centres' separation as the solver saw it, at the step's
     * start). dyn4j's position correction moves discs apart without momentum, so the virial does not see
     * it, as the pressure on a real wall would not.
     */
    private final class Listener extends ContactListenerAdapter<Tagged> {
        @Override
        public void preSolve(ContactCollisionData<Tagged> data, Contact contact) {
            int a = data.getBody1().id;
            int b = data.getBody2().id;
            if (a < 0 && b < 0) {
                return; // two walls: static, nothing to solve
            }
            double contactDistance;
            double e;
            if (a >= 0 && b >= 0) {
                contactDistance = d.radius[a] + d.radius[b];
                e = restitution.pair(a, b, stepEnd);
            } else {
                int disc = Math.max(a, b);
                contactDistance = d.radius[disc];
                e = restitution.wall(disc, stepEnd);
            }
            deepestOverlap = Math.max(deepestOverlap, contact.getDepth() / contactDistance);
            data.getContactConstraint().setRestitution(e);
            data.getContactConstraint().setRestitutionVelocity(0);
        }

        @Override
        public void postSolve(ContactCollisionData<Tagged> data, SolvedContact contact) {
            if (!(contact.getNormalImpulse() > 0)) {
                return;
            }
            int a = data.getBody1().id;
            int b = data.getBody2().id;
            if (a >= 0 && b >= 0) {
                pairCollisions++;
                double dx = bodies[a].getTransform().getTranslationX() - bodies[b].getTransform().getTranslationX();
                double dy = bodies[a].getTransform().getTranslationY() - bodies[b].getTransform().getTranslationY();
                virial.add(stepEnd, contact.getNormalImpulse() * Math.sqrt(dx * dx + dy * dy));
            } else {
                wallCollisions++;
            }
            collided(a);
            collided(b);
        }

        private void collided(int id) {
            if (id >= 0 && d.invMass[id] > 0) {
                restitution.collided(id, stepEnd);
            }
        }
    }
}
