// How a bench script that a developer runs fails, the same in each: a bad argument named in one line before
// anything is served or written (exit 2), a failed run in one line (exit 1), its stack only with --stack.

/** Says what is wrong with the arguments, as `tool: message`, and exits 2. */
export function usage(tool, message) {
  console.error(`${tool}: ${message}`);
  process.exit(2);
}

/** Runs `main` (async); a failure prints its message in one line (its stack with --stack) and exits 1. */
export function runMain(tool, main) {
  main().catch((error) => {
    const message = String(error?.message ?? error);
    // A message that names its tool already (bundle.mjs's say `bench: `) is printed as it is.
    console.error(process.argv.includes('--stack') ? error : /^[\w-]+: /.test(message) ? message : `${tool}: ${message}`);
    process.exit(1);
  });
}
