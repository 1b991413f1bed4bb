//! `grader gradescope DIR`: the Gradescope autograder bundle — the pristine workspace with
//! `setup.sh` (run once, as root) and `run_autograder` (each submission graded by
//! `grader grade --submission`, `submission.rs`, as the grading users).

use std::path::Path;

use crate::submission::{NOT_COPIED, mirror, under};

/// `grader gradescope DIR`: the autograder bundle. Gradescope unzips it into
/// `/autograder/source` and runs `setup.sh` there once (as root), then
/// `run_autograder` for each submission; so DIR holds the pristine workspace
/// (hidden checks included) with the two scripts at its top.
pub fn bundle(root: &Path, dir: &Path, force: bool) -> Result<(), String> {
    if dir.exists() {
        if !force || !dir.join("run_autograder").is_file() {
            return Err(format!("{} exists (use --force to replace an earlier bundle)", dir.display()));
        }
        std::fs::remove_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    let root = root.canonicalize().map_err(|e| format!("{}: {e}", root.display()))?;
    mirror(&root, dir, &|relative| !under(relative, NOT_COPIED) && !relative.ends_with("/target"))?;
    let toolchain = env!("CARGO_PKG_RUST_VERSION");
    let setup = SETUP.replace("{TOOLCHAIN}", toolchain).replace("{USER}", GRADING_USER);
    write_script(&dir.join("setup.sh"), &setup)?;
    write_script(&dir.join("run_autograder"), &RUN_AUTOGRADER.replace("{USER}", GRADING_USER))?;
    println!(
        "Gradescope bundle written to {}.\nZip its contents (setup.sh and run_autograder at the top) and upload \
         them as the autograder:\n  (cd {} && zip -qr ../autograder.zip .)",
        dir.display(),
        dir.display()
    );
    Ok(())
}

/// The user the bundle builds and runs the student's code as: it cannot read
/// `/autograder/source`, where the judge, the snapshots and the hidden checks are.
pub const GRADING_USER: &str = "raylab-student";

fn write_script(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    crate::platform::make_executable(path)
}

/// Gradescope runs this once, as root, to build the autograder image.
const SETUP: &str = r#"#!/usr/bin/env bash
# raylab autograder, run once as root when Gradescope builds the image (scripts/gradescope-e2e.sh
# runs it the same way on any Linux machine). It
#  1. finds a Rust toolchain (cargo on the PATH or in ~/.cargo), installing one only when none is found;
#  2. makes the grading users, {USER} and one more per further core ({USER}-2, …: each grades one
#     check at a time, so a check's processes count against its own user's limit), and gives them
#     read-only copies of the toolchain and of the crates' sources in /usr/local/lib/raylab (hard
#     links where the file system allows), and nothing else: the autograder's source, where the
#     judge, the snapshots and the hidden checks are, is root's alone;
#  3. builds the grader and grades the reference once (the judge as root, the student's side as
#     {USER}), so that grading a submission rebuilds only the lectures it changes.
set -euo pipefail
AUTOGRADER=/autograder
SOURCE="$AUTOGRADER/source"
SHARED=/usr/local/lib/raylab
USER_NAME={USER}

# 1. A toolchain.
if ! command -v cargo > /dev/null && [ -f "$HOME/.cargo/env" ]; then
  source "$HOME/.cargo/env"
fi
if command -v cargo > /dev/null; then
  echo "setup: using the installed toolchain: $(cargo --version)"
else
  echo "setup: no Rust toolchain found; installing {TOOLCHAIN} with rustup"
  apt-get update -q
  apt-get install -y -q --no-install-recommends build-essential curl ca-certificates
  curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs \
    | sh -s -- -y --profile minimal --default-toolchain {TOOLCHAIN}
  source "$HOME/.cargo/env"
fi

# 2. The grading users, and what they may read.
USERS="$USER_NAME"
for n in $(seq 2 "$(nproc)"); do USERS="$USERS,$USER_NAME-$n"; done
for user in ${USERS//,/ }; do
  id "$user" > /dev/null 2>&1 || useradd --system --no-create-home --shell /usr/sbin/nologin "$user"
done
share() { # share FROM TO: a read-only copy owned by root, hard-linked where possible
  rm -rf "$2"
  mkdir -p "$(dirname "$2")"
  cp -al "$1" "$2" 2> /dev/null || cp -a "$1" "$2"
  chmod -R a+rX "$2"
}
SYSROOT="$(rustc --print sysroot)"
if runuser -u "$USER_NAME" -- "$SYSROOT/bin/cargo" --version > /dev/null 2>&1; then
  TOOLCHAIN_BIN="$SYSROOT/bin"
else
  share "$SYSROOT" "$SHARED/toolchain"
  TOOLCHAIN_BIN="$SHARED/toolchain/bin"
fi
REGISTRY="${CARGO_HOME:-$HOME/.cargo}/registry"
if [ -d "$REGISTRY" ] && [ ! -d "$SHARED/cargo/registry" ]; then
  share "$REGISTRY" "$SHARED/cargo/registry"
fi
mkdir -p "$SHARED/cargo"
printf 'export PATH="%s:$PATH"\nexport CARGO_HOME="%s"\nexport CARGO_NET_OFFLINE=true\nexport RAYLAB_USERS="%s"\n' \
  "$TOOLCHAIN_BIN" "$SHARED/cargo" "$USERS" > "$SHARED/env"
# The crates' sources: fetched once here (the student's builds are offline).
PATH="$TOOLCHAIN_BIN:$PATH" CARGO_HOME="$SHARED/cargo" cargo fetch --locked --manifest-path "$SOURCE/Cargo.toml"
chmod -R a+rX "$SHARED"
chmod 700 "$SOURCE"
chmod o+x "$AUTOGRADER"

# 3. The grader, the judge and the work folder, from the reference.
source "$SHARED/env"
cd "$SOURCE"
cargo build -p grader
./target/debug/grader grade --submission "$SOURCE" --workdir "$AUTOGRADER/work" --run-as "$RAYLAB_USERS" \
  --strict --format json -o /tmp/raylab-reference.json
echo "setup: the reference scores full marks"
"#;

/// Gradescope runs this for each submission.
const RUN_AUTOGRADER: &str = r#"#!/usr/bin/env bash
# raylab autograder: grades /autograder/submission (only its lectures/*/src is read) with the
# hidden checks, the student's code built and run as {USER} and its siblings (setup.sh), and writes
# /autograder/results/results.json.
set -uo pipefail
source /usr/local/lib/raylab/env
mkdir -p /autograder/results
cd /autograder/source
if ! ./target/debug/grader grade --submission /autograder/submission --workdir /autograder/work \
    --run-as "$RAYLAB_USERS" --format gradescope -o /autograder/results/results.json 2> /tmp/grader.err; then
  if [ ! -s /autograder/results/results.json ]; then
    python3 -c '
import json
err = open("/tmp/grader.err").read()[-4000:]
json.dump({"score": 0, "output": "The grader could not grade this submission:\n" + err,
           "stdout_visibility": "visible"}, open("/autograder/results/results.json", "w"))
'
  fi
fi
"#;
