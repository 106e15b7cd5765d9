// What the page needs to know of an H.264 access unit (Annex B, as
// `foxglove_msgs/msg/CompressedVideo` carries it) before handing it to WebCodecs: whether
// it starts a picture chain, and the codec string the decoder is configured with. Only NAL
// headers and the three bytes after an SPS's header are read, never picture data.

const NAL_IDR = 5;
const NAL_SPS = 7;

/** The NAL units of an Annex B byte stream: the bytes after each start code. */
export function* nalUnits(au: Uint8Array): Generator<Uint8Array> {
  let start = -1;
  let i = 0;
  while (i + 2 < au.length) {
    if (au[i] === 0 && au[i + 1] === 0 && au[i + 2] === 1) {
      if (start >= 0) {
        // A four-byte start code's leading zero belongs to it, not to the unit before.
        let end = i;
        if (end > start && au[end - 1] === 0) end--;
        yield au.subarray(start, end);
      }
      i += 3;
      start = i;
    } else i++;
  }
  if (start >= 0 && start < au.length) yield au.subarray(start);
}

/** Whether a decoder can start at this access unit: it holds an IDR slice. */
export function isKeyframe(au: Uint8Array): boolean {
  for (const u of nalUnits(au)) if (u.length > 0 && (u[0] & 0x1f) === NAL_IDR) return true;
  return false;
}

/** The WebCodecs codec string (`avc1.PPCCLL`: profile, constraint flags, level from the
 * SPS), or null when the access unit carries no SPS. */
export function codecString(au: Uint8Array): string | null {
  for (const u of nalUnits(au)) {
    if (u.length >= 4 && (u[0] & 0x1f) === NAL_SPS) {
      const hex = (b: number) => b.toString(16).toUpperCase().padStart(2, "0");
      return `avc1.${hex(u[1])}${hex(u[2])}${hex(u[3])}`;
    }
  }
  return null;
}
