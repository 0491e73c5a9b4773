// The OpenAPI 3 document of the navigation service's API v1 (api.hpp). A test asks every route
// listed here and checks it answers as listed (tests/net/api_test.cpp).

#include "ballsight/net/api.hpp"

namespace ballsight {

const nlohmann::json& openapi_document() {
  static const nlohmann::json document = nlohmann::json::parse(R"json({
  "openapi": "3.0.3",
  "info": {"title": "ballsight navigation service", "version": "1",
           "description": "Where the court cameras see the balls and the robot, and the route the robot should drive (docs/robot-link.md). Writes need 'Authorization: Bearer TOKEN'. Errors: {\"error\", \"where\"}."},
  "components": {
    "securitySchemes": {"bearer": {"type": "http", "scheme": "bearer"}},
    "schemas": {
      "Error": {"type": "object", "required": ["error", "where"],
                "properties": {"error": {"type": "string"}, "where": {"type": "string"}}},
      "Point": {"type": "object", "required": ["x_m", "y_m"], "additionalProperties": false,
                "properties": {"x_m": {"type": "number"}, "y_m": {"type": "number"}}},
      "Pose": {"type": "object", "required": ["x_m", "y_m", "heading_deg"], "additionalProperties": false,
               "properties": {"x_m": {"type": "number"}, "y_m": {"type": "number"}, "heading_deg": {"type": "number"}}},
      "Balls": {"type": "object", "required": ["balls"], "additionalProperties": false,
                "properties": {"balls": {"type": "array", "items": {"$ref": "#/components/schemas/Point"}}}},
      "Drive": {"type": "object", "required": ["seq", "speed_mps", "turn_rate_dps"], "additionalProperties": false,
                "properties": {"seq": {"type": "integer", "minimum": 0}, "speed_mps": {"type": "number"}, "turn_rate_dps": {"type": "number", "description": "counter-clockwise"}}},
      "BallIds": {"type": "object", "required": ["seq", "ids"], "additionalProperties": false,
                  "properties": {"seq": {"type": "integer", "minimum": 1}, "ids": {"type": "array", "items": {"type": "integer", "minimum": 0}}, "held": {"$ref": "#/components/schemas/Held"}}},
      "CollectedBalls": {"type": "object", "required": ["balls"], "additionalProperties": false,
                         "properties": {"balls": {"type": "array", "items": {"$ref": "#/components/schemas/Point"}}, "held": {"$ref": "#/components/schemas/Held"}}},
      "Held": {"type": "integer", "minimum": 0, "maximum": 1000, "description": "balls in the robot's basket now"},
      "Ack": {"type": "object", "required": ["seq"], "additionalProperties": false,
              "properties": {"seq": {"type": "integer", "minimum": 0, "description": "an update published already (else 409)"}}},
      "Update": {"type": "object", "required": ["seq", "service_id", "capture_time_ns", "published_ns", "world", "route"],
                 "properties": {"seq": {"type": "integer"}, "service_id": {"type": "string"}, "capture_time_ns": {"type": "integer"},
                                "published_ns": {"type": "integer"}, "world": {"type": "object"},
                                "route": {"type": "object"},
                                "given_up": {"type": "array", "description": "balls the robot gave up on (POST /api/v1/unreachable), with why",
                                                "items": {"type": "object", "properties": {"x_m": {"type": "number"}, "y_m": {"type": "number"}, "reason": {"type": "string"}}}}}},
      "Unreachable": {"type": "object", "required": ["balls", "reason"], "additionalProperties": false,
                      "properties": {"balls": {"type": "array", "items": {"$ref": "#/components/schemas/Point"}}, "reason": {"type": "string", "minLength": 1, "maxLength": 200}}}
    }
  },
  "paths": {
    "/api/v1/robot": {
      "get": {"summary": "The robot's pose: the cameras' or the last one a client set, whichever is newer",
              "responses": {"200": {"description": "pose"}, "404": {"description": "no pose yet"}}},
      "put": {"summary": "Set the robot's pose (an external localisation)", "security": [{"bearer": []}],
              "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Pose"}}}},
              "responses": {"200": {"description": "set"}, "400": {"description": "bad body"}, "401": {"description": "no token"}, "422": {"description": "outside the field"}}}
    },
    "/api/v1/balls": {
      "get": {"summary": "The balls: the cameras' or the last list a client set, whichever is newer",
              "responses": {"200": {"description": "balls"}}},
      "put": {"summary": "Publish balls (an external detector)", "security": [{"bearer": []}],
              "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Balls"}}}},
              "responses": {"200": {"description": "set"}, "400": {"description": "bad body"}, "401": {"description": "no token"}, "422": {"description": "outside the field"}}}
    },
    "/api/v1/navigation": {
      "get": {"summary": "Without 'after': the latest and the acknowledged sequence numbers and the service id. With 'after': long-poll for the first update newer than it (the latest when 'after' is 0, beyond the latest, or of another run named by 'service')",
              "parameters": [{"name": "after", "in": "query", "schema": {"type": "integer", "minimum": 0}},
                             {"name": "service", "in": "query", "schema": {"type": "string"}},
                             {"name": "timeout_ms", "in": "query", "schema": {"type": "integer", "minimum": 0, "maximum": 30000}}],
              "responses": {"200": {"description": "status, or the update", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Update"}}}},
                            "204": {"description": "no newer update within timeout_ms"}, "400": {"description": "bad query"}}}
    },
    "/api/v1/navigation/ack": {
      "post": {"summary": "Mark update 'seq' read (the report's flag)", "security": [{"bearer": []}],
               "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Ack"}}}},
               "responses": {"200": {"description": "acknowledged"}, "400": {"description": "bad body"}, "401": {"description": "no token"}, "409": {"description": "not published"}}}
    },
    "/api/v1/collected": {
      "post": {"summary": "Balls the robot picked up, as positions {\"balls\": [...]} or as indices into an update's world model {\"seq\": N, \"ids\": [...]}: they leave the plan at once (re-planned and published), until the cameras confirm them gone. Either may carry \"held\": the balls in the robot's basket now (0 after emptying it; the route plans the unload trips with it)", "security": [{"bearer": []}],
               "requestBody": {"required": true, "content": {"application/json": {"schema": {"oneOf": [{"$ref": "#/components/schemas/CollectedBalls"}, {"$ref": "#/components/schemas/BallIds"}]}}}},
               "responses": {"200": {"description": "accepted"}, "400": {"description": "bad body"}, "401": {"description": "no token"}, "409": {"description": "that update is not kept"}, "422": {"description": "outside the field, or no such ball"}}}
    },
    "/api/v1/unreachable": {
      "post": {"summary": "Balls the robot gave up on after a bounded number of tries, with why: left out of every route from now on (re-planned and published), listed in every update's 'unreachable'", "security": [{"bearer": []}],
               "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Unreachable"}}}},
               "responses": {"200": {"description": "accepted"}, "400": {"description": "bad body"}, "401": {"description": "no token"}, "422": {"description": "outside the field"}}}
    },
    "/api/v1/sim/drive": {
      "put": {"summary": "The simulated court only: the simulated robot's command for update 'seq' (it drives the next vision period; the court waits for it). Answers {\"collected\": balls its collector took since its previous command, \"time_s\": simulated time, \"odometry\": the wheels' odometry at the update's frames (a Pose, in the odometry's own frame: it drifts as wheels slip)}", "security": [{"bearer": []}],
              "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Drive"}}}},
              "responses": {"200": {"description": "driving"}, "400": {"description": "bad body"}, "401": {"description": "no token"}, "404": {"description": "not a simulated court"}}}
    },
    "/api/v1/world": {
      "get": {"summary": "The latest world model: balls, collection sites, obstacles, robot, cameras; its seq, service id, capture and publish times",
              "responses": {"200": {"description": "world model"}, "503": {"description": "no update yet"}}}
    },
    "/api/v1/route": {
      "get": {"summary": "The latest route: order, waypoints, length, time; its seq, service id, capture and publish times",
              "responses": {"200": {"description": "route"}, "503": {"description": "no update yet"}}}
    },
    "/api/v1/site": {
      "get": {"summary": "The court the service watches: its size, fenced area and net, the cameras' names, the ball radius, and whether it is the simulated court",
              "responses": {"200": {"description": "site"}}}
    },
    "/api/v1/health": {
      "get": {"summary": "The service: cameras, rates, latency, clients", "responses": {"200": {"description": "health"}}}
    },
    "/api/v1/stream": {
      "get": {"summary": "WebSocket: every update newer than 'after', in order, as the chosen topics ({\"topic\": \"navigation\", \"update\"}, {\"topic\": \"world\", ...}, {\"topic\": \"health\", ...} once a second); gaps in seq are updates missed",
              "parameters": [{"name": "after", "in": "query", "schema": {"type": "integer", "minimum": 0}},
                             {"name": "service", "in": "query", "schema": {"type": "string"}},
                             {"name": "topics", "in": "query", "schema": {"type": "string", "example": "navigation,world,health"}}],
              "responses": {"101": {"description": "switching to WebSocket"}, "400": {"description": "bad query"},
                            "426": {"description": "not a WebSocket upgrade"}}}
    },
    "/api/v1/openapi.json": {
      "get": {"summary": "This document", "responses": {"200": {"description": "OpenAPI 3"}}}
    },
    "/api/v1/planner": {
      "get": {"summary": "The planner of the next routes and the choices", "responses": {"200": {"description": "{planner, choices}"}, "404": {"description": "no planner on this service"}}},
      "put": {"summary": "Choose the planner (priority, nearest, ballsight); the last world model is planned again at once", "security": [{"bearer": []}],
              "requestBody": {"required": true, "content": {"application/json": {"schema": {"type": "object", "required": ["planner"], "properties": {"planner": {"type": "string", "enum": ["priority", "nearest", "ballsight"]}}}}}},
              "responses": {"200": {"description": "{planner, choices}"}, "400": {"description": "bad body"}, "401": {"description": "no token"}, "404": {"description": "no planner on this service"}, "422": {"description": "no such planner"}}}
    },
    "/api/v1/cameras/{camera}/view": {
      "get": {"summary": "A camera's last frame through the pipeline: {camera, seq, capture_time_ns, width, height, detections: [{object, x_px, y_px, radius_px}] in the frame's pixels, image: a JPEG at most 640 px wide as a data: URL}",
              "responses": {"200": {"description": "view"}, "404": {"description": "no such camera, or no frame from it yet"}}}
    },
    "/api/v1/court-calibration/site": {
      "get": {"summary": "Court calibration: the site's cameras {name, width, height, calibration_file or null}, its reference balls {name, x_m, y_m, z_m} and whether calibration files are written here",
              "responses": {"200": {"description": "site"}, "404": {"description": "no court calibration on this service"}}}
    },
    "/api/v1/court-calibration/stills": {
      "post": {"summary": "Court calibration: keep a camera's last frame to work on. Body {camera: name}; answers {still: id, camera, width, height}",
               "responses": {"201": {"description": "still"}, "400": {"description": "bad body"}, "404": {"description": "no such camera"}, "409": {"description": "no frame from it yet"}, "422": {"description": "bad value"}}}
    },
    "/api/v1/court-calibration/stills/{still}": {
      "get": {"summary": "Court calibration: the still as PNG", "responses": {"200": {"description": "image/png"}, "404": {"description": "no such still"}}}
    },
    "/api/v1/court-calibration/stills/{still}/pose": {
      "post": {"summary": "Court calibration: the reference balls found in the still and the camera's pose fitted to them (ballsight court calibrate), with the body's corrections {placed: [{reference, x_px, y_px}], absent: [name]}. Answers {references: [{name, state: found|placed|absent|missing, seen, projected, residual_px}], blobs, matched, rms_px, max_px, camera_position_m}, or with ?format=yaml the camera's calibration file with that pose",
               "parameters": [{"name": "format", "in": "query", "schema": {"type": "string", "enum": ["json", "yaml"]}}],
               "responses": {"200": {"description": "pose"}, "400": {"description": "bad body or format"}, "404": {"description": "no such still"}, "422": {"description": "too few reference balls (found and missing named), or no such reference"}}}
    },
    "/api/v1/court-calibration/stills/{still}/calibration": {
      "put": {"summary": "Court calibration: write the pose (as POST .../pose fits it) into the camera's calibration file", "security": [{"bearer": []}],
              "responses": {"200": {"description": "pose, and written: the file"}, "400": {"description": "bad body"}, "401": {"description": "no token"}, "404": {"description": "no such still"}, "409": {"description": "this service has no calibration files"}, "422": {"description": "too few reference balls"}}}
    },
    "/api/v1/court-calibration/stills/{still}/colours": {
      "post": {"summary": "Court calibration: a ball colour model learned from clicked ball pixels (ballsight colours learn). Body {clicks: [{x_px, y_px}]}; answers {colours: the model, balls: [{x_px, y_px, radius_px, score}] it finds in the still}, or with ?format=file the model's file",
               "parameters": [{"name": "format", "in": "query", "schema": {"type": "string", "enum": ["json", "file"]}}],
               "responses": {"200": {"description": "model"}, "400": {"description": "bad body"}, "404": {"description": "no such still"}, "422": {"description": "a click outside the image, or on no colour"}}}
    },
    "/api/v1/omni/files": {
      "get": {"summary": "Omni calibration: the images of the server's folder (serve --omni-frames) and whether a simulated omni robot is there",
              "responses": {"200": {"description": "{\"files\": [names], \"simulated\": bool}"}}}
    },
    "/api/v1/omni/frames": {
      "post": {"summary": "Omni calibration: a frame to work on, the body a PNG or JPEG image, or {\"file\": NAME} of the server's folder, or {\"simulated\": true}. Answers {\"frame\": id, width, height, source, rim: the mirror's rim circle {x_px, y_px, radius_px} or null}",
               "responses": {"201": {"description": "frame"}, "400": {"description": "bad JSON"}, "404": {"description": "no such file, or no files or simulation here"},
                             "413": {"description": "too large"}, "415": {"description": "not an image"}, "422": {"description": "not readable"}}}
    },
    "/api/v1/omni/frames/{frame}": {
      "get": {"summary": "Omni calibration: the frame as PNG", "responses": {"200": {"description": "image/png"}, "404": {"description": "no such frame"}}}
    },
    "/api/v1/omni/frames/{frame}/markers": {
      "post": {"summary": "Omni calibration: the layout's floor markers found in the frame (ballsight omni markers). Body {center: {x_px, y_px}, layout: {bearing_step_deg, min_cm, max_cm, step_cm}, marker_bgr: [b, g, r], marker_diameter_cm}; answers {markers: [{x_px, y_px, distance_cm, bearing_deg}], blobs, layout_markers}",
               "responses": {"200": {"description": "markers"}, "400": {"description": "bad body"}, "404": {"description": "no such frame"}, "422": {"description": "bad layout"}}}
    },
    "/api/v1/omni/frames/{frame}/table": {
      "post": {"summary": "Omni calibration: a table made before (ballsight's format, the body) to check points against; it must be for the frame's image size. Answers {table: id, method, width, height, center, valid_radius}",
               "responses": {"201": {"description": "table"}, "404": {"description": "no such frame"}, "415": {"description": "not a ballsight table"}, "422": {"description": "for another image size, truncated or corrupt"}}}
    },
    "/api/v1/omni/tables/{table}/residuals": {
      "post": {"summary": "Omni calibration: every point's residual under a checked table (its floor point at the point's pixel). Body {points: [{x_px, y_px, distance_cm, bearing_deg}]}; answers {residuals, out_of_range, distance_cm: {count, median, p95, max}}",
               "responses": {"200": {"description": "residuals"}, "400": {"description": "bad body"}, "404": {"description": "no such table"}, "422": {"description": "bad value"}}}
    },
    "/api/v1/omni/places": {
      "post": {"summary": "Omni calibration: each point's place in the layout (its ray, and its ring by a fit's distance or by its rank on the ray). Body {center, layout, points: [{x_px, y_px}], fit: id or null}",
               "responses": {"200": {"description": "{points: [{x_px, y_px, distance_cm, bearing_deg}]}"}, "400": {"description": "bad body"}, "404": {"description": "no such fit"}, "422": {"description": "bad layout"}}}
    },
    "/api/v1/omni/samples": {
      "post": {"summary": "Omni calibration: the samples CSV of points (ballsight omni fit --samples). Body {center, points: [{x_px, y_px, distance_cm, bearing_deg}]}",
               "responses": {"200": {"description": "text/csv"}, "400": {"description": "bad body"}, "422": {"description": "bad value"}}}
    },
    "/api/v1/omni/points": {
      "post": {"summary": "Omni calibration: the points of a samples CSV (the body) taken around ?center=X,Y",
               "parameters": [{"name": "center", "in": "query", "required": true, "schema": {"type": "string", "example": "319.5,239.5"}}],
               "responses": {"200": {"description": "{points: [...]}"}, "400": {"description": "no centre"}, "422": {"description": "bad CSV (line and column named)"}}}
    },
    "/api/v1/omni/fits": {
      "post": {"summary": "Omni calibration: fit a method (poly, paper-mlp, ballsight) to points on its own thread, as ballsight omni fit --center --image-size on the exported samples. Body {method, center, image: {width, height}, points}",
               "responses": {"202": {"description": "{fit: id, state: running}"}, "400": {"description": "bad body"}, "422": {"description": "bad value"}, "429": {"description": "two fits running"}}}
    },
    "/api/v1/omni/fits/{fit}": {
      "get": {"summary": "Omni calibration: a fit's state (running, done, failed: error), and when done its errors, every point's residual and the distance-vs-radius curves of 12 directions",
              "responses": {"200": {"description": "fit"}, "404": {"description": "no such fit"}}}
    },
    "/api/v1/omni/fits/{fit}/table": {
      "get": {"summary": "Omni calibration: a fit's lookup table, ?format=ballsight (docs/lut-format.md) or iris (the IRIS team's int16 px2cm)",
              "parameters": [{"name": "format", "in": "query", "schema": {"type": "string", "enum": ["ballsight", "iris"]}}],
              "responses": {"200": {"description": "application/octet-stream"}, "400": {"description": "bad format"}, "404": {"description": "no such fit"}, "409": {"description": "not done"}}}
    }
  }
})json");
  return document;
}

}  // namespace ballsight
