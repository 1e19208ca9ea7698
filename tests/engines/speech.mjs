// Real voices for the engines that take them from the system: Firefox speaks through speech-dispatcher
// (libspeechd autospawns it), here with a configuration of the suite's own in a folder of its own, whose
// one output module says the text with espeak-ng and throws the sound away (no sound card on a test machine).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

// speech-dispatcher's generic module: espeak-ng synthesises the whole text (so the voice's own time to
// speak is its synthesis time), its WAV goes to /dev/null, and the module says `end` when espeak-ng exits.
const MODULE = `GenericExecuteSynth "printf %s \\'$DATA\\' | espeak-ng -v $VOICE -s $RATE -p $PITCH -q --stdin --stdout > /dev/null"
GenericCmdDependency "espeak-ng"
GenericRateAdd 175
GenericRateMultiply 100
GenericRateForceInteger 1
GenericPitchAdd 50
GenericPitchMultiply 50
GenericPitchForceInteger 1
GenericLanguage "en" "en" "utf-8"
GenericLanguage "en-us" "en-us" "utf-8"
GenericLanguage "en-gb" "en-gb" "utf-8"
GenericLanguage "fr" "fr" "utf-8"
AddVoice "en" "MALE1" "en-us"
AddVoice "en-us" "MALE1" "en-us"
AddVoice "en-gb" "MALE1" "en-gb"
AddVoice "fr" "MALE1" "fr"
DefaultVoice "en-us"
`;

// The module's own audio output is opened at its start though it plays nothing: libao opens no device
// then (Pulse and ALSA would fail where there is no sound server or card).
const DISPATCHER = `LogLevel 2
AudioOutputMethod "libao"
AddModule "espeak-ng" "sd_generic" "espeak-ng-silent.conf"
DefaultModule espeak-ng
DefaultLanguage "en-US"
`;

/**
 * The environment that gives a browser speech-dispatcher's voices from a configuration of the suite's
 * own (made in a new temporary folder, removed when the process exits): XDG_CONFIG_HOME and
 * XDG_RUNTIME_DIR, where libspeechd finds the configuration and puts the daemon's socket.
 */
export function speechEnvironment() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'conecurl-speech-'));
  const config = path.join(dir, 'config');
  const runtime = path.join(dir, 'run');
  fs.mkdirSync(path.join(config, 'speech-dispatcher/modules'), { recursive: true });
  fs.mkdirSync(runtime, { mode: 0o700 });
  fs.writeFileSync(path.join(config, 'speech-dispatcher/speechd.conf'), DISPATCHER);
  fs.writeFileSync(path.join(config, 'speech-dispatcher/modules/espeak-ng-silent.conf'), MODULE);
  process.once('exit', () => fs.rmSync(dir, { recursive: true, force: true }));
  return { XDG_CONFIG_HOME: config, XDG_RUNTIME_DIR: runtime };
}
