package carom.engines.cluster;

/**
 * Marker of every message the cluster engine sends between JVMs: Akka's configuration binds it to
 * the Jackson CBOR serializer ({@link ClusterLife#config}).
 */
public interface ClusterMessage {
}
