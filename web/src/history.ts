// Undo and redo: a list of states and a position in it. Pure and generic (the page keeps
// design steps in it: designHistory.ts), unit-tested in Node. Recording a state after an undo
// drops the states that were ahead (the usual editor rule); the oldest states go once the list
// is full, so memory stays bounded however long the session.
export class History<T> {
  private entries: T[] = [];
  private position = -1; // index of the current state; -1 when empty

  constructor(private readonly limit = 100) {
    if (!Number.isInteger(limit) || limit < 1) throw new Error('history limit must be a whole number >= 1');
  }

  // Starts over with one state (a new mesh): nothing to undo.
  reset(state: T): void {
    this.entries = [state];
    this.position = 0;
  }

  clear(): void {
    this.entries = [];
    this.position = -1;
  }

  get current(): T | null {
    return this.entries[this.position] ?? null;
  }

  get canUndo(): boolean {
    return this.position > 0;
  }

  get canRedo(): boolean {
    return this.position >= 0 && this.position < this.entries.length - 1;
  }

  get size(): number {
    return this.entries.length;
  }

  get index(): number {
    return this.position;
  }

  get all(): readonly T[] {
    return this.entries;
  }

  // A new state after the current one (one edit, one paint stroke).
  push(state: T): void {
    this.entries = this.entries.slice(0, this.position + 1);
    this.entries.push(state);
    if (this.entries.length > this.limit) this.entries.splice(0, this.entries.length - this.limit);
    this.position = this.entries.length - 1;
  }

  // Changes what the current state records (e.g. the solve that reproduces it), not a new step.
  replaceCurrent(state: T): void {
    if (this.position < 0) throw new Error('no current state to replace');
    this.entries[this.position] = state;
  }

  // Drops the current state and the states ahead of it (a step that failed); the one before
  // becomes current and is returned, or null when there is none (the first state stays).
  discardCurrent(): T | null {
    if (this.position <= 0) return null;
    this.entries = this.entries.slice(0, this.position);
    this.position -= 1;
    return this.entries[this.position]!;
  }

  // The state undo leads to (now current), or null when there is none.
  undo(): T | null {
    if (!this.canUndo) return null;
    this.position -= 1;
    return this.entries[this.position]!;
  }

  redo(): T | null {
    if (!this.canRedo) return null;
    this.position += 1;
    return this.entries[this.position]!;
  }
}
