// How `conecurl publish` fails: a PublishError carries the one line a user reads (what failed, what to do)
// and the exit code; anything else is a bug, shown as one line too unless --debug asks for the stack.

/** Exit codes: 1 bad input (the PDF, the out folder), 2 bad usage (arguments), 3 a site with failed pages. */
export const EXIT = { input: 1, usage: 2, incomplete: 3 };

export class PublishError extends Error {
  /** @param {string} message one line: what failed and what to do @param {number} code an EXIT value */
  constructor(message, code = EXIT.input) {
    super(message);
    this.name = 'PublishError';
    this.code = code;
  }
}

export const usageError = (message) => new PublishError(message, EXIT.usage);
export const inputError = (message) => new PublishError(message, EXIT.input);

/** Writes `error` to stderr as one line (with the stack under --debug) and returns its exit code. */
export function report(error, debug) {
  if (error instanceof PublishError) {
    process.stderr.write(`conecurl publish: ${error.message}\n`);
    if (debug && error.cause) process.stderr.write(`${error.cause.stack ?? error.cause}\n`);
    return error.code;
  }
  const line = String(error?.message ?? error).split('\n')[0];
  process.stderr.write(`conecurl publish: unexpected failure: ${line} (run again with --debug for details)\n`);
  if (debug) process.stderr.write(`${error?.stack ?? error}\n`);
  return EXIT.input;
}
