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
  /** Map coordinates → CSS pixels inside the robot view's map canvas (for click tests). */
  mapToScreen: ((x: number, y: number) => [number, number]) | null;
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
  mapToScreen: null,
};

export function count(panel: string) {
  probe.frames[panel] = (probe.frames[panel] ?? 0) + 1;
}

(globalThis as any).fleetlink = probe;
