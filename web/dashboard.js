// The live dashboard (/): the court from above with the latest navigation update of the service's
// stream (/api/v1/stream, docs/robot-link.md), and the service's health. What is drawn is also in
// window.ballsightDashboard ({seq, balls, robot, route}), for tests and the browser's console.
import { drawCourtMap, drawSparkline } from "/web/court_map.js";

const LATENCY_POINTS = 60;
const RECONNECT_MS = [250, 500, 1000, 2000, 4000];
const CAMERA_PERIOD_MS = 2000; // each camera's frame, at a low rate
const MARKER_COLOURS = { ball: "#ffe14d", robot_front_marker: "#ff4d4d", robot_back_marker: "#4da3ff" };

const $ = (id) => document.getElementById(id);
const state = { site: null, update: null, latencies: [], serviceId: "", seq: 0, retries: 0 };
window.ballsightDashboard = { seq: 0, balls: [], robot: null, route: null, cameras: {} };

function showError(message) {
  const box = $("error");
  box.textContent = message;
  box.hidden = !message;
}

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
  Object.assign(window.ballsightDashboard, { seq: update.seq, balls: world.balls, robot: world.robot, route });
  state.latencies.push((update.published_ns - update.capture_time_ns) / 1e6);
  state.latencies.splice(0, Math.max(0, state.latencies.length - LATENCY_POINTS));
  drawSparkline($("latency"), state.latencies);
}

function showHealth(health) {
  $("frame-sets").textContent = String(health.frame_sets ?? "-");
  $("rate").textContent = `${fixed(health.frame_sets_per_s, 1)} /s`;
  $("pipeline").textContent = `${fixed(health.pipeline_ms, 1)} ms, plan ${fixed(health.plan_ms, 1)} ms`;
  $("collected").textContent = health.sim ? `${health.sim.collected} (${health.sim.balls_left} left)` : "-";
  const list = $("cameras");
  list.replaceChildren(
    ...(health.cameras ?? []).map((camera) => {
      const item = document.createElement("li");
      item.textContent = `${camera.name}: ${camera.state}`;
      if (camera.state !== "ok" && camera.state !== "simulated") item.className = "failed";
      return item;
    }),
  );
}

function connect() {
  const query = new URLSearchParams({ topics: "navigation,health", after: String(state.seq) });
  if (state.serviceId) query.set("service", state.serviceId);
  const socket = new WebSocket(`ws://${location.host}/api/v1/stream?${query}`);
  socket.onopen = () => {
    state.retries = 0;
    $("connection").textContent = "live";
    showError("");
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

async function refreshCameras() {
  const figures = $("camera-views").querySelectorAll("figure");
  for (const [i, name] of state.site.cameras.entries()) {
    try {
      await showCameraView(name, figures[i]);
    } catch (error) {
      figures[i].querySelector("figcaption").textContent = `${name}: ${error.message}`;
    }
  }
  setTimeout(refreshCameras, CAMERA_PERIOD_MS);
}

function showPlannerError(message) {
  $("planner-error").textContent = message;
  $("planner-error").hidden = !message;
}

async function plannerRequest(init) {
  const response = await fetch("/api/v1/planner", init);
  const answer = await response.json();
  if (!response.ok) throw new Error(`${answer.where}: ${answer.error}`);
  $("planner").value = answer.planner;
  return answer;
}

$("use-planner").addEventListener("click", async () => {
  showPlannerError("");
  try {
    await plannerRequest({
      method: "PUT",
      headers: { "Content-Type": "application/json", Authorization: `Bearer ${$("token").value}` },
      body: JSON.stringify({ planner: $("planner").value }),
    });
  } catch (error) {
    showPlannerError(error.message);
  }
});

async function start() {
  try {
    const response = await fetch("/api/v1/site");
    if (!response.ok) throw new Error(`/api/v1/site: ${response.status} ${await response.text()}`);
    state.site = await response.json();
  } catch (error) {
    showError(`cannot read the site: ${error.message}`);
    $("connection").textContent = "offline";
    return;
  }
  drawCourtMap($("court"), state.site, null);
  connect();
  cameraPanels();
  refreshCameras();
  plannerRequest({}).catch((error) => showPlannerError(error.message));
}

start();
