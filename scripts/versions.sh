# Version checks shared by the scripts (sourced: . scripts/versions.sh).

# The first dotted version number in the input: "cmake version 3.25.1" -> 3.25.1.
first_version() {
  sed -n 's/^[^0-9]*\([0-9][0-9]*\.[0-9][0-9]*\(\.[0-9][0-9]*\)\{0,1\}\).*/\1/p' | head -n 1
}

# Whether version $1 is $2 or later, comparing major, minor and patch as numbers.
version_at_least() {
  awk -v found="$1" -v wanted="$2" 'BEGIN {
    split(found, f, "."); split(wanted, w, ".")
    for (i = 1; i <= 3; i++) if (f[i] + 0 != w[i] + 0) exit !(f[i] + 0 > w[i] + 0)
    exit 0
  }'
}
