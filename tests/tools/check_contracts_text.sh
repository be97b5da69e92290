#!/usr/bin/env bash
# Headers and docs state contracts and current facts, not the history of how they were reached:
# no issue numbers of this project ("issue 14", "#45") in source or docs, and no doc linking into
# an archive of logs. Another project's issue ("ericw-tools issue #261") names a fact and may
# stay. Usage: check_contracts_text.sh SOURCE_DIR; prints each offending line, fails if any.
set -uo pipefail
root=${1:?usage: check_contracts_text.sh SOURCE_DIR}
cd "$root"
found=0
issue_numbers=$(grep -rnE '\b[Ii]ssues? #?[0-9]+|\(#[0-9]+\)' --include='*.h' --include='*.cpp' --include='*.md' \
  --include='*.sh' --include='*.py' --include='CMakeLists.txt' \
  app docs report tests ui visibility wld README.md 2>/dev/null | grep -v 'ericw' | grep -v 'check_contracts_text.sh')
if [ -n "$issue_numbers" ]; then
  echo "issue numbers (say what holds instead; history belongs in commits):"
  echo "$issue_numbers"
  found=1
fi
history_links=$(grep -rnE '\]\((\.\./)?(docs/)?history/' docs README.md 2>/dev/null)
if [ -n "$history_links" ]; then
  echo "links into a history archive:"
  echo "$history_links"
  found=1
fi
exit $found
