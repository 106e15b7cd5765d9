// The robot view's camera panel: a robot's video topics (`foxglove_msgs/msg/CompressedVideo`,
// H.264 encoded on the robot) played with WebCodecs, and its `CompressedImage` topics shown
// picture by picture; a selector in the panel's title picks one. Video comes first where the
// browser decodes it; where it cannot (no WebCodecs, the stream's profile unsupported, a
// decoder error before the first picture) the panel falls back to the robot's JPEG topic
// and says why. The title shows the frame rate drawn and the bytes per second received.
//
// Design choice: the decoder is fed every frame in order from a keyframe on. The hub gives
// a new subscriber the last keyframe and the frames since, and never a frame whose
// predecessor was lost (docs/video.md), so the page only has to wait for a keyframe when it
// starts or falls behind by itself.

import type { TopicInfo } from "../api";
import { codecString, isKeyframe } from "../h264";
import { bytesOf, imageKind } from "../messages";
import { count, probe } from "../probe";
import type { Rosbridge } from "../rosbridge";
import { bps, el, num } from "./dom";

export const VIDEO_TYPE = "foxglove_msgs/msg/CompressedVideo";
const IMAGE_TYPE = "sensor_msgs/msg/CompressedImage";
/** Frames waiting in the decoder before the page skips to the next keyframe. */
const MAX_DECODE_QUEUE = 8;

interface Panel {
  box: HTMLElement;
  body: HTMLElement;
  info: HTMLElement;
}

/** Frames and bytes over the last second, for the panel's title. */
class Meter {
  private frames: number[] = [];
  private bytes: [number, number][] = [];
  frame() {
    this.frames.push(performance.now());
  }
  received(n: number) {
    this.bytes.push([performance.now(), n]);
  }
  read(): { fps: number; bps: number } {
    const since = performance.now() - 2000;
    this.frames = this.frames.filter((t) => t >= since);
    this.bytes = this.bytes.filter(([t]) => t >= since);
    return { fps: this.frames.length / 2, bps: this.bytes.reduce((s, [, n]) => s + n, 0) / 2 };
  }
}

/**
 * Fills the camera panel; returns the topics it may show (for the inspector to leave
 * alone), or an empty list when the robot has no camera topic.
 */
export function cameraPanel(p: Panel, rb: Rosbridge, own: TopicInfo[], cleanups: (() => void)[], note: (topic: string, msg: any) => void): string[] {
  const videos = own.filter((t) => t.type === VIDEO_TYPE);
  const images = own.filter((t) => t.type === IMAGE_TYPE);
  if (!videos.length && !images.length) {
    p.body.appendChild(el("p", "muted", "This robot publishes no camera topic (CompressedVideo or CompressedImage)."));
    return [];
  }
  const webcodecs = typeof VideoDecoder !== "undefined";
  const sel = el("select");
  for (const t of videos) sel.appendChild(new Option(`${t.name} · H.264`, t.name));
  for (const t of images) sel.appendChild(new Option(`${t.name} · picture by picture`, t.name));
  sel.value = (videos[0] ?? images[0]).name;
  p.box.querySelector("h2")!.appendChild(sel);
  const msgLine = el("p", "muted");
  const view = el("div");
  p.body.append(view, msgLine);
  probe.video = { topic: "", codec: "", width: 0, height: 0, decoded: 0, errors: 0, fallback: "" };

  let stop: (() => void) | null = null;
  /** Why the panel shows what it shows, when it is not what was asked for. */
  let reason = "";
  const show = (name: string, why = "") => {
    stop?.();
    view.replaceChildren();
    msgLine.textContent = reason = why;
    sel.value = name;
    const t = own.find((x) => x.name === name)!;
    stop = t.type === VIDEO_TYPE ? playVideo(t) : showPictures(t);
  };
  /** The video cannot be played here: the first JPEG topic instead, with the reason. */
  const fallBack = (why: string) => {
    probe.video.fallback = why;
    if (images[0]) show(images[0].name, `${why}: showing ${images[0].name} instead.`);
    else {
      stop?.();
      stop = null;
      msgLine.textContent = `${why}; this robot has no JPEG camera topic to show instead.`;
    }
  };

  function playVideo(t: TopicInfo): () => void {
    const cv = el("canvas", "camera video");
    view.appendChild(cv);
    const g = cv.getContext("2d")!;
    const meter = new Meter();
    let decoder: VideoDecoder | null = null;
    let codec = "";
    /** Frames taken while the decoder is being set up, fed to it once it is. */
    let pending: EncodedVideoChunk[] | null = null;
    let needKey = true;
    let stopped = false;
    if (!webcodecs) {
      queueMicrotask(() => fallBack("this browser has no WebCodecs video decoder"));
      return () => {};
    }
    const v = probe.video;
    Object.assign(v, { topic: t.name, codec: "", width: 0, height: 0, decoded: 0, errors: 0, fallback: "" });

    const open = async (first: EncodedVideoChunk, au: Uint8Array) => {
      codec = codecString(au) ?? "avc1.42E01E";
      v.codec = codec;
      pending = [first];
      const config: VideoDecoderConfig = { codec, optimizeForLatency: true };
      let supported = false;
      try {
        supported = !!(await VideoDecoder.isConfigSupported(config)).supported;
      } catch {
        supported = false;
      }
      if (stopped) return;
      if (!supported) {
        fallBack(`this browser cannot decode ${codec} video`);
        return;
      }
      const d = new VideoDecoder({
        output: (frame) => {
          if (cv.width !== frame.displayWidth || cv.height !== frame.displayHeight) {
            cv.width = frame.displayWidth;
            cv.height = frame.displayHeight;
          }
          g.drawImage(frame, 0, 0);
          v.width = frame.displayWidth;
          v.height = frame.displayHeight;
          frame.close();
          v.decoded++;
          meter.frame();
          count("camera");
          count("video");
        },
        error: (e) => {
          v.errors++;
          decoder = null;
          needKey = true;
          if (v.decoded === 0) fallBack(`the video did not decode (${e.message})`);
          else msgLine.textContent = `decoder error (${e.message}); resuming at the next keyframe`;
        },
      });
      d.configure(config);
      decoder = d;
      for (const c of pending ?? []) d.decode(c);
      pending = null;
    };

    let seq = 0;
    const unsub = rb.subscribe(t.name, (msg) => {
      note(t.name, { header: { stamp: msg.timestamp } });
      const au = bytesOf(msg.data);
      meter.received(au.length);
      if (msg.format !== "h264") {
        msgLine.textContent = `${t.name} carries ${msg.format} video, not h264`;
        return;
      }
      const key = isKeyframe(au);
      if (decoder && decoder.decodeQueueSize > MAX_DECODE_QUEUE) needKey = true; // behind
      if (needKey && !key) return;
      needKey = false;
      // Timestamps only order the frames; the stream's own count serves.
      const chunk = new EncodedVideoChunk({ type: key ? "key" : "delta", timestamp: seq++ * 1000, data: au });
      if (pending) pending.push(chunk);
      else if (decoder) decoder.decode(chunk);
      else if (key) void open(chunk, au);
    }, { type: t.type, queue_length: 30 });
    const timer = window.setInterval(() => {
      const m = meter.read();
      p.info.textContent = `${t.name} · ${codec || "waiting for a keyframe"}${v.width ? ` · ${v.width}×${v.height}` : ""} · ${num(m.fps)} fps · ${bps(m.bps)}`;
    }, 1000);
    return () => {
      stopped = true;
      unsub();
      clearInterval(timer);
      if (decoder && decoder.state !== "closed") decoder.close();
      decoder = null;
    };
  }

  // CompressedImage → <img> when the bytes decode, else a view of the bytes themselves.
  function showPictures(t: TopicInfo): () => void {
    const img = el("img", "camera");
    const cv = el("canvas", "camera bytes");
    cv.style.display = "none";
    view.append(img, cv);
    const meter = new Meter();
    let url = "", busy = false, last = "";
    const unsub = rb.subscribe(t.name, async (msg) => {
      note(t.name, msg);
      count("camera");
      const data = bytesOf(msg.data);
      meter.received(data.length);
      if (busy) return; // decoding the previous frame still; this one is skipped
      busy = true;
      const kind = imageKind(data);
      try {
        const blob = new Blob([data as BlobPart], { type: `image/${kind === "png" ? "png" : "jpeg"}` });
        const bmp = await createImageBitmap(blob);
        bmp.close();
        if (url) URL.revokeObjectURL(url);
        url = URL.createObjectURL(blob);
        img.src = url;
        img.style.display = "";
        cv.style.display = "none";
        meter.frame();
        msgLine.textContent = reason;
        last = `${msg.format} · ${(data.length / 1024).toFixed(0)} KiB`;
      } catch {
        // Not a decodable image (a format the browser cannot read, a corrupt or
        // truncated frame): show the bytes as grey levels so the stream is still visible.
        img.style.display = "none";
        cv.style.display = "";
        const side = Math.max(1, Math.floor(Math.sqrt(data.length)));
        cv.width = side; cv.height = side;
        const g = cv.getContext("2d")!;
        const px = g.createImageData(side, side);
        for (let i = 0; i < side * side; i++) {
          const v = data[i];
          px.data[i * 4] = px.data[i * 4 + 1] = px.data[i * 4 + 2] = v;
          px.data[i * 4 + 3] = 255;
        }
        g.putImageData(px, 0, 0);
        msgLine.textContent = `not a decodable ${msg.format} image (${kind === "unknown" ? "no image header" : `${kind} header, undecodable body`}): showing its ${data.length.toLocaleString()} bytes as grey levels`;
        last = `${msg.format} · ${(data.length / 1024).toFixed(0)} KiB`;
      } finally {
        busy = false;
      }
    }, { type: t.type, queue_length: 1 });
    const timer = window.setInterval(() => {
      const m = meter.read();
      p.info.textContent = `${t.name}${last ? ` · ${last}` : ""} · ${num(m.fps)} fps · ${bps(m.bps)}`;
    }, 1000);
    return () => {
      unsub();
      clearInterval(timer);
      if (url) URL.revokeObjectURL(url);
    };
  }

  sel.addEventListener("change", () => show(sel.value));
  show(sel.value);
  cleanups.push(() => stop?.());
  return [...videos, ...images].map((t) => t.name);
}
