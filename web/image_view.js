// An image on a canvas with zoom and pan: image pixel (x, y) is drawn at canvas
// (x * scale + tx, y * scale + ty), pixel centres at integers (OpenCV's and the API's convention).

export class ImageView {
  constructor(canvas) {
    this.canvas = canvas;
    this.scale = 1;
    this.tx = 0;
    this.ty = 0;
    this.width = 0;
    this.height = 0;
  }

  /// Shows a whole image of `width` x `height` centred in the canvas.
  fit(width, height) {
    this.width = width;
    this.height = height;
    const c = this.canvas;
    this.scale = Math.min(c.width / width, c.height / height);
    this.tx = 0.5 * (c.width - width * this.scale) + 0.5 * this.scale;
    this.ty = 0.5 * (c.height - height * this.scale) + 0.5 * this.scale;
  }

  /// Zooms by `factor` keeping the image point under canvas (cx, cy) where it is.
  zoomAt(cx, cy, factor) {
    const scale = Math.min(64, Math.max(0.05, this.scale * factor));
    const [x, y] = this.imageFromCanvas(cx, cy);
    this.scale = scale;
    this.tx = cx - x * scale;
    this.ty = cy - y * scale;
  }

  panBy(dx, dy) {
    this.tx += dx;
    this.ty += dy;
  }

  imageFromCanvas(cx, cy) {
    return [(cx - this.tx) / this.scale, (cy - this.ty) / this.scale];
  }

  canvasFromImage(x, y) {
    return [x * this.scale + this.tx, y * this.scale + this.ty];
  }

  /// Canvas pixel of a mouse event (the canvas may be drawn at another size than its pixels).
  canvasFromClient(clientX, clientY) {
    const r = this.canvas.getBoundingClientRect();
    return [(clientX - r.left) * this.canvas.width / r.width,
            (clientY - r.top) * this.canvas.height / r.height];
  }

  /// Client (page) coordinates of an image point: where a click lands on it.
  clientFromImage(x, y) {
    const r = this.canvas.getBoundingClientRect();
    const [cx, cy] = this.canvasFromImage(x, y);
    return [r.left + cx * r.width / this.canvas.width, r.top + cy * r.height / this.canvas.height];
  }

  /// Draws `image` (an ImageBitmap or <img>) under the current transform.
  draw(ctx, image) {
    ctx.imageSmoothingEnabled = this.scale < 2;
    ctx.drawImage(image, this.tx - 0.5 * this.scale, this.ty - 0.5 * this.scale,
                  this.width * this.scale, this.height * this.scale);
  }
}
