// Counters the page exposes on `window.fleetlink` so tests (and curious operators in the
// devtools console) can see what was drawn: frames per panel, last poses, last results.

export interface Probe {
  frames: Record<string, number>;
  poses: Record<string, { x: number; y: number; yaw: number; at: number }>;
  feedback: number[];
  lastResult: unknown;
  lastServiceResponse: unknown;
  disabled: Record<string, string>;
  renders: number;
  cloudAgesMs: number[];
  /** Milliseconds spent, summed: decoding frames, unpacking clouds, drawing clouds. */
  busyMs: { decode: number; cloudUnpack: number; cloudRender: number };
  /** The robot map's marker layer at its last drawing: markers per type and namespace. */
  markers: { drawn: number; shapes: number; byType: Record<string, number>; byNs: Record<string, number> };
  /** Map coordinates → CSS pixels inside the robot view's map canvas (for click tests). */
  mapToScreen: ((x: number, y: number) => [number, number]) | null;
  /** The robot view's configuration panel: loaded, whether the operator may change it,
   * the changes in force, the last apply's outcome. */
  config: { loaded: boolean; mayChange: boolean; overlay: unknown; result: string };
  /** The camera panel's video: the topic played, its codec string, the size and number of
   * pictures decoded, decoder errors, and why it fell back to pictures (empty if not). */
  video: { topic: string; codec: string; width: number; height: number; decoded: number; errors: number; fallback: string };
}

export const probe: Probe = {
  frames: {},
  poses: {},
  feedback: [],
  lastResult: null,
  lastServiceResponse: null,
  disabled: {},
  renders: 0,
  cloudAgesMs: [],
  busyMs: { decode: 0, cloudUnpack: 0, cloudRender: 0 },
  markers: { drawn: 0, shapes: 0, byType: {}, byNs: {} },
  mapToScreen: null,
  config: { loaded: false, mayChange: false, overlay: null, result: "" },
  video: { topic: "", codec: "", width: 0, height: 0, decoded: 0, errors: 0, fallback: "" },
};

export function count(panel: string) {
  probe.frames[panel] = (probe.frames[panel] ?? 0) + 1;
}

(globalThis as any).fleetlink = probe;
