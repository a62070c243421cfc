import carom.core.scene.*;
import carom.core.state.Discs;
import carom.core.engine.*;
import carom.engines.kernel.*;
import carom.engines.EngineCatalog;
import carom.core.observe.StateChecks;

public class Phases {
    public static void main(String[] a) {
        int n = Integer.parseInt(a[0]);
        int reps = Integer.parseInt(a[1]);
        for (int r = 0; r < reps; r++) {
            long t0 = System.nanoTime();
            Scene scene = StandardScenes.thesis(n, 42 + r);
            long t1 = System.nanoTime();
            Discs src = scene.newDiscs();
            long t2 = System.nanoTime();
            DiscTable table = new DiscTable(scene, src, 1);
            long t3 = System.nanoTime();
            DiscMotion motion = new DiscMotion(table);
            CellPredictor p = new CellPredictor(motion);
            CalendarQueue q = table.newCalendar(n);
            for (int i = 0; i < n; i++) {
                if (table.invMass(i) > 0) table.setEventTime(i, p.predictFull(i, 0));
            }
            long t4 = System.nanoTime();
            table.planCalendar(q, null, n, 0, 0.85);
            long t5 = System.nanoTime();
            RunResult res = EngineCatalog.byName("fast").run(scene, RunOptions.until(scene.until()));
            long t6 = System.nanoTime();
            // What every summary checks at the end: the final state's deepest overlap.
            double deepest = StateChecks.deepestOverlap(res.finalState(), scene.box());
            long t7 = System.nanoTime();
            System.out.printf("n=%d gen %.0f ms, newDiscs %.0f ms, table %.0f ms, predict %.0f ms, plan %.0f ms | whole fast run %.0f ms (wallSeconds %.0f ms) pairs %d | final check %.0f ms (deepest %.1e)%n",
                n, (t1-t0)/1e6, (t2-t1)/1e6, (t3-t2)/1e6, (t4-t3)/1e6, (t5-t4)/1e6, (t6-t5)/1e6, res.wallSeconds()*1e3, res.pairCollisions(), (t7-t6)/1e6, deepest);
        }
    }
}
