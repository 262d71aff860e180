/**
 * A promise kept in a task of its own: work started after it (a table fill's program built with
 * three's compileAsync, whose first stage runs at once) is not part of the task that asked for it
 * (the render that found the fill missing), which would then be as long as both.
 */
export const nextTask = (): Promise<void> => new Promise((resolve) => setTimeout(resolve, 0));
