# Sourced by bench/roomseg/run.sh and transforms.sh (needs `here`, the bench folder, set first):
# sets `maps`, the Bormann et al. test-map folder, and `names`, its 20 segmentation maps
# (ROOMSEG_MAPS="map1 map2 ...": a subset); exits 0 with a message when ../shared is absent.
# variant_suffix VARIANT: the file-name suffix of a map variant (exits 2 on an unknown one).
maps=${KSMC_SHARED_DIR:-$here/../../../shared}/data/maps/bormann_ipa/test_maps
if [ ! -d "$maps" ]; then
  echo "bench/roomseg: $maps is absent; skipped"
  exit 0
fi
names=(Freiburg101_scan Freiburg52_scan Freiburg79_scan NLB lab_a_scan lab_b_scan lab_c_scan lab_d_scan
       lab_f_scan lab_intel lab_ipa office_a office_b office_c office_d office_e office_f office_g
       office_h office_i)
if [ -n "${ROOMSEG_MAPS:-}" ]; then read -r -a names <<< "$ROOMSEG_MAPS"; fi
variant_suffix() {
  case $1 in
    unfurnished) echo "" ;;
    furnished) echo _furnitures ;;
    trashbins) echo _trashbins ;;
    furnished_trashbins) echo _furnitures_trashbins ;;
    *) echo "bench/roomseg: unknown variant '$1' (unfurnished, furnished, trashbins, furnished_trashbins)" >&2; exit 2 ;;
  esac
}
