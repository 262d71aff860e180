/** The benchmark's task pool: its stages run in lanes, each lane one task after another. */

export interface LaneTask<Lane> {
  /** expected time, relative to the other tasks' */
  readonly cost: number;
  /** the task's work, in the lane it is given (where that lane's rows run) */
  readonly run: (lane: Lane) => Promise<void>;
}

/**
 * Runs the tasks, one lane each at once: with one lane one by one in their order, with several the
 * costliest first so that no long one is left running alone at the end.
 */
export async function runAtOnce<Lane>(tasks: readonly LaneTask<Lane>[], lanes: readonly Lane[]): Promise<void> {
  const queue = lanes.length === 1 ? [...tasks] : [...tasks].sort((a, b) => b.cost - a.cost);
  const runner = async (lane: Lane) => {
    for (let task = queue.shift(); task; task = queue.shift()) await task.run(lane);
  };
  await Promise.all(lanes.map(runner));
}
