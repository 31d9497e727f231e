# Sourced by .ci/run: a throw-away PostgreSQL for the collector's PostgreSQL test (PostgresCollectorTest).
# Installs the Debian package when absent (as root), starts a private cluster in a temporary directory on a
# free localhost port (never the system's cluster or port 5432), creates user and database "hapticon" with a
# random password, exports HAPTICON_POSTGRES_URL, and stops and deletes the cluster when the shell exits.
# Without PostgreSQL (and not root) it says so and exports nothing: the test then fails on CI (CI=true).

hapticon_pg_start() {
    local bin
    bin="$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -1)"
    if [ -z "$bin" ] && [ "$(id -u)" = 0 ]; then
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq postgresql >/dev/null \
            || { DEBIAN_FRONTEND=noninteractive apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq postgresql >/dev/null; }
        bin="$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -1)"
    fi
    if [ -z "$bin" ]; then
        echo "CI: PostgreSQL is not installed and this is not root; install it (apt-get install postgresql)" >&2
        return 0
    fi
    # initdb refuses to run as root: as root the cluster belongs to the package's "postgres" user.
    local as=()
    HAPTICON_PG_DIR="$(mktemp -d /tmp/hapticon-pg.XXXXXX)"
    if [ "$(id -u)" = 0 ]; then
        chown postgres "$HAPTICON_PG_DIR"
        as=(runuser -u postgres --)
    fi
    local port password
    port="$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
    password="$(python3 -c 'import secrets; print(secrets.token_hex(16))')"
    "${as[@]}" "$bin/initdb" -D "$HAPTICON_PG_DIR/data" -U postgres --auth-local=trust --auth-host=scram-sha-256 >/dev/null
    "${as[@]}" "$bin/pg_ctl" -D "$HAPTICON_PG_DIR/data" -l "$HAPTICON_PG_DIR/log" -w \
        -o "-c listen_addresses=127.0.0.1 -p $port -k $HAPTICON_PG_DIR" start >/dev/null
    HAPTICON_PG_STOP=("${as[@]}" "$bin/pg_ctl" -D "$HAPTICON_PG_DIR/data" -m fast stop)
    trap 'hapticon_pg_stop' EXIT
    "${as[@]}" "$bin/psql" -q -h "$HAPTICON_PG_DIR" -p "$port" -U postgres -d postgres -v ON_ERROR_STOP=1 \
        -c "CREATE USER hapticon PASSWORD '$password'" -c "CREATE DATABASE hapticon OWNER hapticon"
    export HAPTICON_POSTGRES_URL="postgresql://127.0.0.1:$port/hapticon?user=hapticon&password=$password"
    echo "CI: PostgreSQL $("$bin/postgres" --version | awk '{print $3}') on 127.0.0.1:$port (HAPTICON_POSTGRES_URL set)"
}

hapticon_pg_stop() {
    [ -n "${HAPTICON_PG_DIR:-}" ] || return 0
    "${HAPTICON_PG_STOP[@]}" >/dev/null 2>&1 || true
    rm -rf "$HAPTICON_PG_DIR"
}

hapticon_pg_start
