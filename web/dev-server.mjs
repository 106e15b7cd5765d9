// Development server: serves the freshly built bundle (crates/hub/assets/dashboard) and
// passes everything else — REST and the rosbridge WebSocket — to a running hub, so the
// page can be iterated on without rebuilding the hub binary.
//
//   node dev-server.mjs --hub 127.0.0.1:8080 [--listen 127.0.0.1:5173]
import { readFileSync } from "node:fs";
import http from "node:http";
import net from "node:net";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";

const { values: o } = parseArgs({ options: { hub: { type: "string", default: "127.0.0.1:8080" }, listen: { type: "string", default: "127.0.0.1:5173" } } });
const dist = join(dirname(fileURLToPath(import.meta.url)), "..", "crates", "hub", "assets", "dashboard");
const types = { "/": ["index.html", "text/html"], "/app.js": ["app.js", "text/javascript"], "/app.css": ["app.css", "text/css"] };
const [hubHost, hubPort] = o.hub.split(":");

const server = http.createServer((req, res) => {
  const path = new URL(req.url, "http://x").pathname;
  const file = types[path];
  if (file && req.method === "GET") {
    res.writeHead(200, { "content-type": `${file[1]}; charset=utf-8`, "cache-control": "no-store" });
    res.end(readFileSync(join(dist, file[0])));
    return;
  }
  const up = http.request({ host: hubHost, port: hubPort, method: req.method, path: req.url, headers: req.headers }, (r) => {
    res.writeHead(r.statusCode, r.headers);
    r.pipe(res);
  });
  up.on("error", (e) => { res.writeHead(502); res.end(String(e)); });
  req.pipe(up);
});
// WebSocket upgrades: replay the request head to the hub and splice the sockets.
server.on("upgrade", (req, socket, head) => {
  const up = net.connect(Number(hubPort), hubHost, () => {
    up.write(`${req.method} ${req.url} HTTP/1.1\r\n${Object.entries(req.headers).map(([k, v]) => `${k}: ${v}`).join("\r\n")}\r\n\r\n`);
    up.write(head);
    socket.pipe(up).pipe(socket);
  });
  up.on("error", () => socket.destroy());
  socket.on("error", () => up.destroy());
});
const [host, port] = o.listen.split(":");
server.listen(Number(port), host, () => console.log(`dashboard dev server on http://${o.listen}/ → hub ${o.hub}`));
