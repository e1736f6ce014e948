# make reproduce: deps -> build -> runs -> analysis -> report. Until the pipeline issue lands
# this is a small demo: one run of the default config that writes an output file.
reproduce: build
	mkdir -p runs
	$(BUILD)/sim/apps/crumple-sim protocols/demo.yaml -o runs/demo.h5
	@echo "wrote runs/demo.h5"
