# Sourced by the scripts: sets $bin to the demsweep binary — $DEMSWEEP_BIN if given (a frozen
# copy while the tree is being edited), else a fresh release build in ${CARGO_TARGET_DIR:-target}.
if [ -z "${DEMSWEEP_BIN:-}" ]; then
    cargo build --release --quiet
    bin="${CARGO_TARGET_DIR:-$(pwd)/target}/release/demsweep"
else
    bin=$DEMSWEEP_BIN
fi
