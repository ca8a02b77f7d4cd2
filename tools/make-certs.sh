#!/usr/bin/env bash
# Makes a test PKI for DDS Security with openssl: one CA (EC P-256), a certificate per
# cloudshape participant, and the signed governance and least-privilege permissions.
#
#   tools/make-certs.sh OUTDIR
#
# OUTDIR then holds what CLOUDSHAPE_SECURITY_DIR / --security needs (docs/dds.md "DDS Security"):
#   ca.pem                      the CA certificate (identity CA and permissions CA in one)
#   governance.xml, .p7s        every topic on domains 0..232: authenticated participants only,
#                               access control, discovery/liveliness/metadata/data ENCRYPTed
#   cloudshape-NAME/            one per participant (ingest planes keypoints classifier solver
#                               inject echo): cert.pem, key.pem, permissions.xml, .p7s
#   private/ca.key              the CA key (mode 600; only this script needs it)
# Idempotent: what exists and still verifies against ca.pem is kept; a document is signed
# again only when its text changed or the CA is newer. A test CA, for tests and demos only.
set -euo pipefail

usage() { sed -n '2,16s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; }
die() { printf 'make-certs.sh: %s\n' "$*" >&2; exit 1; }

case "${1:-}" in
  -h|--help) usage; exit 0 ;;
  "") usage >&2; exit 2 ;;
esac
(($# == 1)) || { usage >&2; exit 2; }
command -v openssl >/dev/null 2>&1 || die "openssl not found (Debian package openssl)"

out="$1"
days=3650
# Domain ids the governance and permissions cover: all a default port mapping allows.
domain_min=0
domain_max=232

# Who publishes and subscribes what (the topic table of README "DDS topics"; ROS 2 topics:
# docs/ros2.md, their default names).
declare -A publishes=(
  [cloudshape-ingest]="cloudshape_filtered_cloud cloudshape_status"
  [cloudshape-planes]="cloudshape_planes cloudshape_status"
  [cloudshape-keypoints]="cloudshape_keypoints cloudshape_status"
  [cloudshape-classifier]="cloudshape_classified cloudshape_status"
  [cloudshape-solver]="cloudshape_result cloudshape_status rt/cloudshape/detections rt/cloudshape/markers"
  [cloudshape-inject]="cloudshape_raw_cloud"
  [cloudshape-echo]=""
)
declare -A subscribes=(
  [cloudshape-ingest]="cloudshape_raw_cloud rt/*"  # rt/*: any ROS 2 PointCloud2 topic (--ros-topic)
  [cloudshape-planes]="cloudshape_filtered_cloud"
  [cloudshape-keypoints]="cloudshape_planes"
  [cloudshape-classifier]="cloudshape_keypoints"
  [cloudshape-solver]="cloudshape_classified"
  [cloudshape-inject]="cloudshape_result"  # it waits for each cloud's result (docs/reliability.md)
  [cloudshape-echo]="cloudshape_result cloudshape_status"
)
participants=(cloudshape-ingest cloudshape-planes cloudshape-keypoints cloudshape-classifier
  cloudshape-solver cloudshape-inject cloudshape-echo)

mkdir -p "$out/private"
chmod 700 "$out/private"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The extensions Fast DDS insists on: a permissions CA without digitalSignature fails every
# participant with "Cannot create participant due to initialization error".
cat >"$work/openssl.cnf" <<'EOF'
[req]
distinguished_name = dn
prompt = no
[dn]
[ca_ext]
basicConstraints = critical, CA:TRUE
keyUsage = critical, keyCertSign, cRLSign, digitalSignature
subjectKeyIdentifier = hash
[identity_ext]
basicConstraints = CA:FALSE
keyUsage = critical, digitalSignature, keyAgreement
subjectKeyIdentifier = hash
authorityKeyIdentifier = keyid
EOF

new_key() { openssl genpkey -algorithm EC -pkeyopt ec_paramgen_curve:P-256 -out "$1" 2>/dev/null; chmod 600 "$1"; }
serial() { printf '0x%s' "$(openssl rand -hex 8)"; }

ca_key="$out/private/ca.key"
ca="$out/ca.pem"
if [[ ! -s "$ca_key" || ! -s "$ca" ]]; then
  new_key "$ca_key"
  openssl req -x509 -new -config "$work/openssl.cnf" -extensions ca_ext -key "$ca_key" \
    -subj "/C=XX/O=cloudshape/CN=cloudshape test CA" -days "$days" -sha256 -set_serial "$(serial)" \
    -out "$ca"
  printf 'make-certs.sh: new CA %s\n' "$ca" >&2
fi

# Permissions are valid as long as the CA; dates in the XML Schema dateTime form (UTC).
xml_date() { date -u -d "$(openssl x509 -in "$ca" -noout "$1" | cut -d= -f2)" +%Y-%m-%dT%H:%M:%S; }
not_before="$(xml_date -startdate)"
not_after="$(xml_date -enddate)"

# Writes stdin to $1 only when the text differs, then signs it as $1.p7s (S/MIME, -text: the
# form Fast DDS reads) when the text changed, the signature is missing or the CA is newer.
write_signed() {
  local xml="$1" p7s="${1%.xml}.p7s"
  cat >"$work/doc.xml"
  if ! cmp -s "$work/doc.xml" "$xml"; then mv "$work/doc.xml" "$xml"; fi
  if [[ ! -s "$p7s" || "$xml" -nt "$p7s" || "$ca" -nt "$p7s" ]]; then
    openssl smime -sign -in "$xml" -text -out "$p7s" -signer "$ca" -inkey "$ca_key"
  fi
}

topic_list() {
  local t
  local -a topics
  read -r -a topics <<<"$1"  # split on spaces without expanding rt/* as a file pattern
  printf '<topics>'
  for t in "${topics[@]}"; do printf '<topic>%s</topic>' "$t"; done
  printf '</topics>'
}

write_signed "$out/governance.xml" <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<!-- cloudshape governance (made by tools/make-certs.sh): only authenticated participants
     join; every topic needs a permission to read or write; discovery, liveliness, submessage
     metadata and payloads are encrypted (AES-GCM). -->
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>$domain_min</min><max>$domain_max</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>NONE</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
EOF

for name in "${participants[@]}"; do
  dir="$out/$name"
  mkdir -p "$dir"
  if [[ ! -s "$dir/key.pem" || ! -s "$dir/cert.pem" ]] ||
     ! openssl verify -CAfile "$ca" "$dir/cert.pem" >/dev/null 2>&1; then
    new_key "$dir/key.pem"
    openssl req -new -config "$work/openssl.cnf" -key "$dir/key.pem" \
      -subj "/C=XX/O=cloudshape/CN=$name" -out "$work/$name.csr"
    openssl x509 -req -in "$work/$name.csr" -CA "$ca" -CAkey "$ca_key" -set_serial "$(serial)" \
      -days "$days" -sha256 -extfile "$work/openssl.cnf" -extensions identity_ext \
      -out "$dir/cert.pem" 2>/dev/null
  fi
  # Fast DDS matches <subject_name> against the certificate in RFC 2253 form (CN first).
  subject="$(openssl x509 -in "$dir/cert.pem" -noout -subject -nameopt RFC2253 | sed 's/^subject=//')"
  publish="" subscribe=""
  [[ -z "${publishes[$name]}" ]] || publish="<publish>$(topic_list "${publishes[$name]}")</publish>"
  [[ -z "${subscribes[$name]}" ]] || subscribe="<subscribe>$(topic_list "${subscribes[$name]}")</subscribe>"
  write_signed "$dir/permissions.xml" <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<!-- Permissions of $name (made by tools/make-certs.sh): exactly the topics it publishes
     and subscribes, nothing else. -->
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="$name">
      <subject_name>$subject</subject_name>
      <validity><not_before>$not_before</not_before><not_after>$not_after</not_after></validity>
      <allow_rule>
        <domains><id_range><min>$domain_min</min><max>$domain_max</max></id_range></domains>
        $publish
        $subscribe
      </allow_rule>
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
EOF
done
printf 'make-certs.sh: %s ready (%d participants)\n' "$out" "${#participants[@]}" >&2
