package carom.core.observe;

/**
 * Several collision observers behind one: each collision goes to every one of them, in order. A plain
 * array and an index loop, so that a collision costs no allocation and no iterator.
 */
final class CollisionFanOut implements CollisionObserver {
    private final CollisionObserver[] observers;

    CollisionFanOut(CollisionObserver[] observers) {
        this.observers = observers.clone();
    }

    @Override
    public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
        for (CollisionObserver o : observers) {
            o.pair(time, i, k, dx, dy, nx, ny, j);
        }
    }

    @Override
    public void wall(double time, int i, int wall, double j) {
        for (CollisionObserver o : observers) {
            o.wall(time, i, wall, j);
        }
    }
}
