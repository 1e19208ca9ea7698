#!/usr/bin/env node
// The `conecurl` command: dispatches its subcommands (today `publish`, which turns a PDF into a static
// site the reader opens), and answers --help and --version.
import { readFileSync } from 'node:fs';

const HELP = `Usage: conecurl <command> [options]

Commands:
  publish <book.pdf> --out <folder>   make a static flipbook site from a PDF (conecurl publish --help)

Options:
  --help      this text
  --version   conecurl's version
`;

const [command, ...rest] = process.argv.slice(2);
if (command === 'publish') {
  const { main } = await import('./publish/main.mjs');
  process.exitCode = await main(rest);
} else if (command === '--version' || command === '-v') {
  const { version } = JSON.parse(readFileSync(new URL('../package.json', import.meta.url), 'utf8'));
  process.stdout.write(`${version}\n`);
} else if (command === undefined || command === '--help' || command === '-h' || command === 'help') {
  process.stdout.write(HELP);
} else {
  process.stderr.write(`conecurl: unknown command "${command}": the commands are: publish (see conecurl --help)\n`);
  process.exitCode = 2;
}
