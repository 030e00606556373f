// Reads a Silva rosbag2 MCAP file with independent readers (@mcap/core for the container, @foxglove/rosmsg and
// @foxglove/rosmsg2-serialization for the ros2msg schemas and CDR payloads) and prints what the Python test
// compares with the dataset's own files: one JSON object on stdout.
// Usage: node read_bag.mjs BAG.mcap
import { open } from "node:fs/promises";
import { createHash } from "node:crypto";
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";

const sha = (bytes) => createHash("sha256").update(bytes).digest("hex");
const stampNs = (h) => BigInt(h.stamp.sec) * 1000000000n + BigInt(h.stamp.nanosec);

const file = await open(process.argv[2]);
const size = (await file.stat()).size;

// Every record in file order with CRC checks (chunk CRCs, the data section CRC, the summary CRC).
const whole = Buffer.alloc(size);
await file.read(whole, 0, size, 0);
const stream = new McapStreamReader({ validateCrcs: true });
stream.append(new Uint8Array(whole.buffer, whole.byteOffset, size));
const opcodes = {};
for (let r; (r = stream.nextRecord()); ) opcodes[r.type] = (opcodes[r.type] ?? 0) + 1;
if (!stream.done()) throw new Error("stream reader did not reach the end magic");

// The indexed reader: summary, chunk indexes and message indexes.
const readable = {
  size: async () => BigInt(size),
  read: async (offset, length) => {
    const buf = Buffer.alloc(Number(length));
    await file.read(buf, 0, Number(length), Number(offset));
    return new Uint8Array(buf.buffer, buf.byteOffset, buf.length);
  },
};
const reader = await McapIndexedReader.Initialize({ readable });
const decoders = new Map();
const schemas = {};
for (const [id, s] of reader.schemasById) {
  const text = new TextDecoder().decode(s.data);
  schemas[s.name] = { encoding: s.encoding };
  decoders.set(id, new MessageReader(parse(text, { ros2: true })));
}
const out = {
  profile: reader.header.profile,
  opcodes,
  schemas,
  chunks: reader.chunkIndexes.length,
  statistics: { messages: Number(reader.statistics.messageCount), channels: reader.statistics.channelCount },
  channels: {},
  messages: [],
};
for (const [, c] of reader.channelsById)
  out.channels[c.topic] = {
    schema: reader.schemasById.get(c.schemaId).name,
    encoding: c.messageEncoding,
    qos: c.metadata.get("offered_qos_profiles") ?? null,
  };
for await (const m of reader.readMessages()) {
  const channel = reader.channelsById.get(m.channelId);
  const msg = decoders.get(channel.schemaId).readMessage(m.data);
  const entry = { topic: channel.topic, log_time: m.logTime.toString(), sequence: m.sequence };
  if (msg.header) {
    entry.stamp = stampNs(msg.header).toString();
    entry.frame_id = msg.header.frame_id;
  }
  if (msg.encoding !== undefined) {
    Object.assign(entry, { width: msg.width, height: msg.height, encoding: msg.encoding, step: msg.step });
    entry.sha256 = sha(msg.data);
  } else if (msg.point_step !== undefined) {
    const n = msg.width * msg.height;
    const view = new DataView(msg.data.buffer, msg.data.byteOffset, msg.data.byteLength);
    const offset = Object.fromEntries(msg.fields.map((f) => [f.name, f.offset]));
    const xyzi = Buffer.alloc(16 * n), labels = Buffer.alloc(4 * n);
    const rings = [], times = [];
    for (let i = 0; i < n; ++i) {
      const p = i * msg.point_step;
      for (const [k, name] of ["x", "y", "z", "intensity"].entries())
        xyzi.writeFloatLE(view.getFloat32(p + offset[name], true), 16 * i + 4 * k);
      const label = view.getUint16(p + offset.label, true), instance = view.getUint16(p + offset.instance, true);
      labels.writeUInt32LE((instance * 65536 + label) >>> 0, 4 * i);
      rings.push(view.getUint16(p + offset.ring, true));
      times.push(view.getFloat32(p + offset.time, true));
    }
    Object.assign(entry, { points: n, point_step: msg.point_step, fields: msg.fields.map((f) => f.name) });
    Object.assign(entry, { xyzi_sha256: sha(xyzi), labels_sha256: sha(labels), rings, times });
  } else if (msg.transforms) {
    entry.transforms = msg.transforms.map((t) => ({
      stamp: stampNs(t.header).toString(),
      parent: t.header.frame_id,
      child: t.child_frame_id,
      t: [t.transform.translation.x, t.transform.translation.y, t.transform.translation.z],
      q: [t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z, t.transform.rotation.w],
    }));
  } else if (msg.child_frame_id !== undefined) {
    const p = msg.pose.pose;
    entry.child = msg.child_frame_id;
    entry.t = [p.position.x, p.position.y, p.position.z];
    entry.q = [p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w];
  } else if (msg.angular_velocity) {
    const v = (x) => [x.x, x.y, x.z];
    Object.assign(entry, { gyro: v(msg.angular_velocity), accel: v(msg.linear_acceleration) });
    Object.assign(entry, { orientation: [msg.orientation.x, msg.orientation.y, msg.orientation.z, msg.orientation.w] });
    Object.assign(entry, { orientation_covariance: Array.from(msg.orientation_covariance) });
    Object.assign(entry, { gyro_covariance: Array.from(msg.angular_velocity_covariance) });
    Object.assign(entry, { accel_covariance: Array.from(msg.linear_acceleration_covariance) });
  } else if (msg.k) {
    Object.assign(entry, { width: msg.width, height: msg.height, k: Array.from(msg.k), p: Array.from(msg.p) });
    Object.assign(entry, { distortion_model: msg.distortion_model, d: Array.from(msg.d) });
  }
  out.messages.push(entry);
}
await file.close();
process.stdout.write(JSON.stringify(out) + "\n");
