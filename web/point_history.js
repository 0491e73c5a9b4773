// The calibration points with undo and redo: every change is a new list, the old ones kept.

export class PointHistory {
  constructor(limit = 200) {
    this.limit = limit;
    this.past = [];
    this.future = [];
    this.points = [];
  }

  /// Replaces the list (a change that can be undone).
  set(points) {
    this.past.push(this.points);
    if (this.past.length > this.limit) this.past.shift();
    this.future = [];
    this.points = points;
  }

  add(point) { this.set([...this.points, point]); }

  update(index, changes) {
    this.set(this.points.map((p, i) => (i === index ? { ...p, ...changes } : p)));
  }

  remove(index) { this.set(this.points.filter((_, i) => i !== index)); }

  undo() {
    if (!this.past.length) return false;
    this.future.push(this.points);
    this.points = this.past.pop();
    return true;
  }

  redo() {
    if (!this.future.length) return false;
    this.past.push(this.points);
    this.points = this.future.pop();
    return true;
  }
}
