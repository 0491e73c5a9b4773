// The live dashboard (/): the court from above with the latest navigation update of the service's
// stream (/api/v1/stream, docs/robot-link.md), and the service's health. What is drawn is also in
// window.ballsightDashboard ({seq, balls, robot, route, givenUp}), for tests and the browser's
// console.
import { drawCourtMap, drawSparkline } from "/web/court_map.js";
import { $, api, showError, socketUrl } from "/web/page_support.js";

const LATENCY_POINTS = 60;
const RECONNECT_MS = [250, 500, 1000, 2000, 4000];
const CAMERA_PERIOD_MS = 2000; // each camera's frame, at a low rate
const HEALTH_WAIT_MS = 250; // for the first health document, before the first frames are asked
const MARKER_COLOURS = { ball: "#ffe14d", robot_front_marker: "#ff4d4d", robot_back_marker: "#4da3ff" };

// A camera in one of these states gives no frames it should (docs/robot-link.md, the health
// document): the site's cameras retrying or stopped, a camera node silent, a simulated camera
// failed. Running, starting, waiting for its first frame, a file source finished, a replay: not.
const FAILED_CAMERA_STATES = new Set(["retrying", "stopped", "silent", "failed"]);
const state = { site: null, update: null, health: null, latencies: [], serviceId: "", seq: 0, retries: 0, live: false };
window.ballsightDashboard = { seq: 0, balls: [], robot: null, route: null, cameras: {} };

function fixed(value, digits) {
  return typeof value === "number" && Number.isFinite(value) ? value.toFixed(digits) : "-";
}

function showUpdate(update) {
  drawCourtMap($("court"), state.site, update);
  const { world, route } = update;
  $("seq").textContent = String(update.seq);
  $("balls").textContent = String(world.balls.length);
  $("robot").textContent = world.robot
    ? `${fixed(world.robot.x_m, 2)}, ${fixed(world.robot.y_m, 2)} m, ${fixed(world.robot.heading_deg, 0)} deg`
    : "not seen";
  $("route").textContent = `${route.order.length} balls, ${fixed(route.length_m, 1)} m, ${fixed(route.time_s, 0)} s (${route.planner})`;
  const givenUp = update.given_up ?? [];
  $("given-up").textContent = givenUp.length === 0
    ? "none"
    : givenUp.map((m) => `${fixed(m.x_m, 1)}, ${fixed(m.y_m, 1)} m: ${m.reason}`).join("; ");
  Object.assign(window.ballsightDashboard, { seq: update.seq, balls: world.balls, robot: world.robot, route, givenUp });
  state.latencies.push((update.published_ns - update.capture_time_ns) / 1e6);
  state.latencies.splice(0, Math.max(0, state.latencies.length - LATENCY_POINTS));
  drawSparkline($("latency"), state.latencies);
}

function showHealth(health) {
  state.health = health;
  $("frame-sets").textContent = String(health.frame_sets ?? "-");
  $("rate").textContent = `${fixed(health.frame_sets_per_s, 1)} /s`;
  $("pipeline").textContent = `${fixed(health.pipeline_ms, 1)} ms, plan ${fixed(health.plan_ms, 1)} ms`;
  $("collected").textContent = health.sim ? `${health.sim.collected} (${health.sim.balls_left} left)` : "-";
  if (health.replay && state.live) {
    const file = health.replay.file.split("/").pop();
    $("connection").textContent = `live: replay of ${file}${health.replay.finished ? ", ended" : ""}`;
  }
  const list = $("cameras");
  list.replaceChildren(
    ...(health.cameras ?? []).map((camera) => {
      const item = document.createElement("li");
      item.textContent = `${camera.name}: ${camera.state}`;
      if (FAILED_CAMERA_STATES.has(camera.state)) item.className = "failed";
      return item;
    }),
  );
}

function connect() {
  const query = new URLSearchParams({ topics: "navigation,health", after: String(state.seq) });
  if (state.serviceId) query.set("service", state.serviceId);
  const socket = new WebSocket(socketUrl(`/api/v1/stream?${query}`));
  socket.onopen = () => {
    state.retries = 0;
    state.live = true;
    $("connection").textContent = "live";
    showError("error", null);
  };
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.topic === "navigation") {
      state.seq = message.update.seq;
      state.serviceId = message.update.service_id;
      showUpdate(message.update);
    } else if (message.topic === "health") {
      showHealth(message.health);
    }
  };
  socket.onclose = () => {
    state.live = false;
    const wait = RECONNECT_MS[Math.min(state.retries++, RECONNECT_MS.length - 1)];
    $("connection").textContent = `reconnecting in ${wait} ms`;
    setTimeout(connect, wait);
  };
}

function cameraPanels() {
  $("camera-views").replaceChildren(
    ...state.site.cameras.map((name) => {
      const figure = document.createElement("figure");
      const canvas = document.createElement("canvas");
      canvas.width = 320;
      canvas.height = 180;
      canvas.dataset.camera = name;
      const caption = document.createElement("figcaption");
      caption.textContent = `${name}: no frame yet`;
      figure.append(canvas, caption);
      return figure;
    }),
  );
}

async function showCameraView(name, figure) {
  const response = await fetch(`/api/v1/cameras/${encodeURIComponent(name)}/view`);
  const caption = figure.querySelector("figcaption");
  if (!response.ok) {
    caption.textContent = `${name}: ${(await response.json()).error}`;
    return;
  }
  const view = await response.json();
  const image = new Image();
  image.src = view.image;
  await image.decode();
  const canvas = figure.querySelector("canvas");
  canvas.height = Math.round((canvas.width * view.height) / view.width);
  const ctx = canvas.getContext("2d");
  ctx.drawImage(image, 0, 0, canvas.width, canvas.height);
  const s = canvas.width / view.width;
  for (const d of view.detections) {
    ctx.beginPath();
    ctx.arc((d.x_px + 0.5) * s, (d.y_px + 0.5) * s, Math.max(4, d.radius_px * s), 0, 2 * Math.PI);
    ctx.strokeStyle = MARKER_COLOURS[d.object] || "#fff";
    ctx.lineWidth = 1.5;
    ctx.stroke();
  }
  caption.textContent = `${name}: seq ${view.seq}, ${view.detections.length} detections`;
  window.ballsightDashboard.cameras[name] = { seq: view.seq, width: view.width, height: view.height, detections: view.detections };
}

/// Whether the service has published a frame of camera `name` (its health says so): before that
/// it has no view to give, and the panel keeps saying "no frame yet".
function hasFrame(name) {
  if (!(state.health?.frame_sets > 0)) return false;
  const camera = (state.health.cameras ?? []).find((c) => c.name === name);
  return !camera || camera.frames === undefined || camera.frames > 0;
}

async function refreshCameras() {
  const figures = $("camera-views").querySelectorAll("figure");
  for (const [i, name] of state.site.cameras.entries()) {
    if (!state.live) break; // the service is away: its views wait for the stream to reconnect
    if (!hasFrame(name)) continue;
    try {
      await showCameraView(name, figures[i]);
    } catch (error) {
      figures[i].querySelector("figcaption").textContent = `${name}: ${error.message}`;
    }
  }
  setTimeout(refreshCameras, state.health ? CAMERA_PERIOD_MS : HEALTH_WAIT_MS);
}

/// GET (no `planner`) or PUT /api/v1/planner; shows the service's choice.
async function plannerRequest(planner) {
  const answer = planner === undefined
    ? await api("GET", "/api/v1/planner")
    : await api("PUT", "/api/v1/planner", { planner }, { token: $("token").value });
  $("planner").value = answer.planner;
  return answer;
}

$("use-planner").addEventListener("click", async () => {
  showError("planner-error", null);
  try {
    await plannerRequest($("planner").value);
  } catch (error) {
    showError("planner-error", error);
  }
});

async function start() {
  try {
    state.site = await api("GET", "/api/v1/site");
  } catch (error) {
    showError("error", `cannot read the site: ${error.message}`);
    $("connection").textContent = "offline";
    return;
  }
  drawCourtMap($("court"), state.site, null);
  connect();
  cameraPanels();
  refreshCameras();
  plannerRequest().catch((error) => showError("planner-error", error));
}

start();
